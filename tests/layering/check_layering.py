#!/usr/bin/env python3
"""Checks the one-way layering of include/pdd (see include/pdd/README.md).

Every header under <root>/pdd belongs to a module: the first folder below pdd/ (core, madd,
io, ...), or, for a header directly in pdd/, its stem (errors.hpp: errors; pipeline.hpp belongs
to pipeline/ and may use pipeline/detail/). The table, a ```layering block in
<root>/pdd/README.md, gives each module a level. A header may include:
  - headers of its own module, and of modules on a strictly lower level;
  - a detail/ folder only from inside the folder that owns it (kernels/cgal/detail/ is private
    to kernels/cgal/).
Anything else (an upward or sideways include, another module's detail/) is reported with
file:line, and the exit status is 1. `--self-test` builds a small bad tree in a temporary
folder and checks that each kind of violation is reported (the check can fail).
"""
import pathlib
import re
import sys
import tempfile

INCLUDE = re.compile(r'^\s*#\s*include\s*[<"](pdd/[^>"]+)[>"]')


def read_levels(root):
    readme = (root / "pdd" / "README.md").read_text()
    block = re.search(r"```layering\n(.*?)```", readme, re.S)
    if not block:
        raise SystemExit(f"{root}/pdd/README.md: no ```layering block")
    levels = {}
    for line in block.group(1).splitlines():
        words = line.split("#")[0].split()
        if words:
            for module in words[1:]:
                levels[module] = int(words[0])
    return levels


def module_of(rel, levels):
    """rel: path below <root>, e.g. pdd/madd/detail/split.hpp -> 'madd'."""
    parts = rel.split("/")
    # a folder below pdd/; for a header directly in pdd/, its stem (pipeline.hpp: pipeline)
    name = parts[1] if len(parts) > 2 else parts[1].rsplit(".", 1)[0]
    if name not in levels:
        raise KeyError(name)
    return name


def detail_owner(rel):
    """pdd/kernels/cgal/detail/mesher.hpp -> 'pdd/kernels/cgal/', None without detail/."""
    i = rel.find("/detail/")
    return rel[: i + 1] if i >= 0 else None


def check(root):
    levels = read_levels(root)
    problems = []
    headers = sorted(p for p in (root / "pdd").rglob("*") if p.suffix in (".hpp", ".h"))
    if not headers:
        problems.append(f"{root}/pdd: no headers found")
    for path in headers:
        rel = path.relative_to(root).as_posix()
        try:
            mine = module_of(rel, levels)
        except KeyError as e:
            problems.append(f"{rel}: module {e} is not in the layering table")
            continue
        for number, line in enumerate(path.read_text().splitlines(), start=1):
            m = INCLUDE.match(line)
            if not m:
                continue
            target = m.group(1)
            where = f"{rel}:{number}: includes {target}"
            try:
                theirs = module_of(target, levels)
            except KeyError as e:
                problems.append(f"{where}: module {e} is not in the layering table")
                continue
            owner = detail_owner(target)
            if owner and not (rel.startswith(owner) or owner == f"pdd/{mine}/"):
                problems.append(f"{where}: {owner}detail/ is private to {owner}")
            if theirs != mine and levels[theirs] >= levels[mine]:
                problems.append(f"{where}: {theirs} (level {levels[theirs]}) is not below "
                                f"{mine} (level {levels[mine]})")
    return problems, len(headers)


def self_test():
    with tempfile.TemporaryDirectory() as tmp:
        root = pathlib.Path(tmp)
        files = {
            "pdd/README.md": "```layering\n0 core\n1 madd io\n2 mesh\n```\n",
            "pdd/core/a.hpp": "#include <pdd/core/b.hpp>\n",
            "pdd/core/b.hpp": "",
            "pdd/core/up.hpp": "#include <pdd/mesh/m.hpp>\n",
            "pdd/madd/side.hpp": "#include <pdd/io/x.hpp>\n",
            "pdd/madd/detail/d.hpp": "#include <pdd/core/a.hpp>\n",
            "pdd/io/x.hpp": "#include <pdd/madd/detail/d.hpp>\n",
            "pdd/mesh/m.hpp": "#include \"pdd/madd/side.hpp\"\n#include <pdd/madd/detail/d.hpp>\n",
        }
        for name, text in files.items():
            (root / name).parent.mkdir(parents=True, exist_ok=True)
            (root / name).write_text(text)
        problems, _ = check(root)
        expected = [
            "pdd/core/up.hpp:1: includes pdd/mesh/m.hpp: mesh (level 2) is not below core",
            "pdd/io/x.hpp:1: includes pdd/madd/detail/d.hpp: pdd/madd/detail/ is private",
            "pdd/io/x.hpp:1: includes pdd/madd/detail/d.hpp: madd (level 1) is not below io",
            "pdd/madd/side.hpp:1: includes pdd/io/x.hpp: io (level 1) is not below madd",
            "pdd/mesh/m.hpp:2: includes pdd/madd/detail/d.hpp: pdd/madd/detail/ is private",
        ]
        missing = [e for e in expected if not any(p.startswith(e) for p in problems)]
        if missing or len(problems) != len(expected):
            print("self-test failed; reported:", *problems, "expected:", *expected, sep="\n  ")
            return 1
        print(f"self-test: the {len(expected)} planted violations are reported, nothing else")
        return 0


def main(argv):
    if argv[1:] == ["--self-test"]:
        return self_test()
    if len(argv) != 2:
        print(__doc__)
        return 2
    problems, n = check(pathlib.Path(argv[1]))
    for p in problems:
        print(p)
    print(f"{n} headers checked, {len(problems)} layering violations")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
