#!/usr/bin/env python3
"""Checks that every test file keeps its names in a namespace of its own (CONTRIBUTING.md).

The test executables are unity builds (tests/CMakeLists.txt, PDD_TEST_UNITY_BATCH): files of
one module share a translation unit, so two helpers of the same name in two files would clash
in some batches and not in others. Every tests/<module>/<stem>.cpp (not common/, fuzz/, mpi/,
tsan/, install/: helpers and programs with their own main, outside the unity builds) must
therefore open `namespace <stem> {` after its last #include, with nothing but blank lines and
comments between, and end with `} // namespace <stem>`. A file that does not is
reported with file:line and the exit status is 1. `--self-test` checks, on a temporary tree,
that each kind of mistake is reported (the check can fail).
"""
import pathlib
import sys
import tempfile

SKIP = {"common", "fuzz", "mpi", "tsan", "install", "layering"}


def problems_of(path):
    lines = path.read_text().splitlines()
    stem = path.stem
    includes = [i for i, line in enumerate(lines) if line.startswith("#include")]
    if not includes:
        return [f"{path}:1: no #include"]
    found = []
    opening = f"namespace {stem} {{"
    body = [(i, line) for i, line in enumerate(lines) if i > includes[-1]
            and line.strip() and not line.lstrip().startswith("//")]
    if not body or body[0][1] != opening:
        where = body[0][0] + 1 if body else len(lines)
        found.append(f"{path}:{where}: the first line after the includes must be '{opening}'")
    closing = [(i, line) for i, line in enumerate(lines) if line.strip()]
    if not closing or closing[-1][1] != f"}} // namespace {stem}":
        found.append(f"{path}:{len(lines)}: the file must end with '}} // namespace {stem}'")
    return found


def check(tests):
    files = sorted(p for p in tests.glob("*/*.cpp") if p.parent.name not in SKIP)
    if not files:
        return [f"{tests}: no test files found"]
    return [p for f in files for p in problems_of(f)]


def self_test():
    good = "#include <x>\n\nnamespace a_test {\nint f();\n} // namespace a_test\n"
    cases = {
        "good": (good, 0),
        "missing": ("#include <x>\n\nint f();\n", 2),
        "wrong_name": (good.replace("namespace a_test {", "namespace b_test {"), 1),
        "code_before": ("#include <x>\nint g;\nnamespace a_test {\n} // namespace a_test\n", 1),
        "not_closed": ("#include <x>\nnamespace a_test {\nint f();\n}\n", 1),
    }
    failed = False
    with tempfile.TemporaryDirectory() as tmp:
        for name, (text, expected) in cases.items():
            path = pathlib.Path(tmp) / name / "a_test.cpp"
            path.parent.mkdir()
            path.write_text(text)
            got = len(problems_of(path))
            if got != expected:
                print(f"self-test {name}: {got} problem(s) reported, expected {expected}")
                failed = True
    print("self-test", "failed" if failed else "passed")
    return 1 if failed else 0


def main():
    if sys.argv[1:] == ["--self-test"]:
        return self_test()
    if len(sys.argv) != 2:
        print("usage: check_test_namespaces.py TESTS_DIR | --self-test", file=sys.stderr)
        return 2
    problems = check(pathlib.Path(sys.argv[1]))
    for p in problems:
        print(p)
    print(f"{len(problems)} problem(s)")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
