#!/usr/bin/env python3
"""Runs every code example of pdd's documentation against a build tree (issue 38 item 2).

For README.md and docs/**/*.md, every fenced block whose language is sh, bash, python, cpp or
cmake is an example and must run, unless the line just before its fence says why not:

    <!-- example not run: REASON -->

(an HTML comment: MkDocs and GitHub show nothing). Blocks without a language (usage synopses,
file excerpts, program output) are not examples.
  * sh/bash: `bash -euo pipefail`, in a scratch folder holding `examples/` (a link to the
    repository's) and `build/quickstart` (a link to the build tree, so README's paths work),
    with the build's programs first on PATH and its Python module on PYTHONPATH.
  * python: the build's Python (CMake's Python_EXECUTABLE) in the same folder and environment.
  * cpp: a block with `int main` is a program: it is built with CMake against the build tree
    (find_package(pdd) from it, as a user does), with the first cmake block after it on the same
    page before the next cpp block, else README's, and run in the scratch folder (exit 0 needed).
    A cpp block without `int main` needs a reason not to run.
  * cmake: run by building a program with it (the cpp block it follows, or README's program).
Identical programs and commands are run once. Exit 1 when an example fails or an example lacks
both a run and a reason; each is reported as file:line.

  python3 scripts/run_doc_examples.py BUILD_DIR [--list] [--only SUBSTRING] [--root DIR]
  python3 scripts/run_doc_examples.py --self-test   # plants failing and unmarked examples
"""
from __future__ import annotations

import argparse
import concurrent.futures
import os
import re
import subprocess
import sys
import tempfile
import time
from dataclasses import dataclass
from pathlib import Path

FENCE = re.compile(r"^```\s*([A-Za-z+]*)\s*$")
NOT_RUN = re.compile(r"^\s*<!--\s*example not run:\s*(.+?)\s*-->\s*$")
LANGUAGES = {"sh": "sh", "bash": "sh", "python": "python", "cpp": "cpp", "cmake": "cmake"}
TIMEOUT_S = 600


@dataclass
class Block:
    path: Path
    line: int  # of the opening fence, 1-based
    language: str  # sh, python, cpp, cmake or "" (not an example)
    text: str
    not_run: str | None  # the reason, when the page gives one

    def where(self, root: Path) -> str:
        return f"{self.path.relative_to(root)}:{self.line}"


def blocks_of(path: Path) -> list[Block]:
    lines = path.read_text(encoding="utf-8").splitlines()
    found: list[Block] = []
    i = 0
    while i < len(lines):
        m = FENCE.match(lines[i])
        if not m:
            i += 1
            continue
        start, body = i, []
        i += 1
        while i < len(lines) and not lines[i].startswith("```"):
            body.append(lines[i])
            i += 1
        reason = NOT_RUN.match(lines[start - 1]) if start > 0 else None
        found.append(Block(path, start + 1, LANGUAGES.get(m.group(1).lower(), ""),
                           "\n".join(body) + "\n", reason.group(1) if reason else None))
        i += 1
    return found


def pages(root: Path) -> list[Path]:
    return [root / "README.md"] + sorted((root / "docs").rglob("*.md"))


class Runner:
    def __init__(self, root: Path, build: Path, scratch: Path):
        self.root, self.build, self.scratch = root, build, scratch
        (scratch / "build").mkdir(parents=True)
        (scratch / "examples").symlink_to(root / "examples", target_is_directory=True)
        (scratch / "build" / "quickstart").symlink_to(build)
        drivers = build / "examples" / "drivers"
        self.env = dict(os.environ)
        self.env["PATH"] = os.pathsep.join([str(drivers), str(drivers / "mpi"), self.env["PATH"]])
        self.env["PYTHONPATH"] = str(build / "python")
        self.env["MPLBACKEND"] = "Agg"
        # mpiexec as root (CI), more ranks than cores, and no DNS wait (docs/reference/pdd-mesh-mpi.md)
        self.env.update({"OMPI_ALLOW_RUN_AS_ROOT": "1", "OMPI_ALLOW_RUN_AS_ROOT_CONFIRM": "1",
                         "OMPI_MCA_rmaps_base_oversubscribe": "1", "HWLOC_COMPONENTS": "-gl"})
        self.done: dict[str, str | None] = {}  # what was run -> its failure (None: passed)
        self.built: dict[tuple[str, str], tuple[Path, str | None]] = {}

    def run(self, what: str, command: list[str], cwd: Path) -> str | None:
        """Runs command once per distinct `what`; returns the failure, or None."""
        if what in self.done:
            return self.done[what]
        try:
            r = subprocess.run(command, cwd=cwd, env=self.env, capture_output=True, text=True,
                               timeout=TIMEOUT_S)
            failure = None if r.returncode == 0 else \
                f"exit {r.returncode}:\n{(r.stdout + r.stderr)[-3000:]}"
        except subprocess.TimeoutExpired:
            failure = f"did not end within {TIMEOUT_S} s"
        self.done[what] = failure
        return failure

    def shell(self, text: str) -> str | None:
        return self.run("sh\n" + text, ["bash", "-euo", "pipefail", "-c", text], self.scratch)

    def python(self, text: str) -> str | None:
        return self.run("python\n" + text, [self.interpreter(), "-c", text], self.scratch)

    def interpreter(self) -> str:
        """The Python the build's module is for (CMake's Python_EXECUTABLE), else this one."""
        cache = self.build / "CMakeCache.txt"
        if cache.is_file():
            for line in cache.read_text(errors="replace").splitlines():
                if line.startswith("Python_EXECUTABLE:FILEPATH="):
                    return line.split("=", 1)[1]
        return sys.executable

    def prebuild(self, programs: list[tuple[str, str]]) -> None:
        """Configures and builds the programs, os.cpu_count() at a time (program() runs them)."""
        with concurrent.futures.ThreadPoolExecutor(max_workers=os.cpu_count() or 1) as pool:
            self.built = dict(zip(programs, pool.map(lambda p: self.build_program(*p), programs)))

    def build_program(self, source: str, cmake: str) -> tuple[Path, str | None]:
        """The program's executable and its build failure (None: built)."""
        project = Path(tempfile.mkdtemp(prefix="program", dir=self.scratch))
        (project / "main.cpp").write_text(source)
        (project / "CMakeLists.txt").write_text(
            "cmake_minimum_required(VERSION 3.25)\nproject(doc_example CXX)\n"
            "add_executable(app main.cpp)\n" + cmake)
        out = project / "build"
        for step in [["cmake", "-S", str(project), "-B", str(out), "-G", "Ninja",
                      "-DCMAKE_BUILD_TYPE=Release", f"-DCMAKE_PREFIX_PATH={self.build}"],
                     ["cmake", "--build", str(out)]]:
            r = subprocess.run(step, cwd=project, env=self.env, capture_output=True, text=True)
            if r.returncode != 0:
                return out / "app", f"{' '.join(step)}: exit {r.returncode}:\n" \
                    f"{(r.stdout + r.stderr)[-3000:]}"
        return out / "app", None

    def program(self, source: str, cmake: str) -> str | None:
        """Builds (unless prebuilt) and runs the program in the scratch folder."""
        built = self.built.get((source, cmake)) or self.build_program(source, cmake)
        executable, failure = built
        if failure:
            return failure
        return self.run("cpp\n" + source + "\ncmake\n" + cmake, [str(executable)], self.scratch)


def programs_of(all_blocks: dict[Path, list[Block]], root: Path, only: str | None,
                default_cmake: str, default_program: str) -> list[tuple[str, str]]:
    """(source, cmake) of every program that check() will build."""
    programs = []
    for blocks in all_blocks.values():
        for i, b in enumerate(blocks):
            if b.not_run or (only and only not in b.where(root)):
                continue
            if b.language == "cpp" and "int main" in b.text:
                programs.append((b.text, cmake_for(blocks, i, default_cmake)))
            elif b.language == "cmake":
                source = next((c.text for c in reversed(blocks[:i])
                               if c.language == "cpp" and "int main" in c.text), default_program)
                programs.append((source, b.text))
    return list(dict.fromkeys(programs))


def cmake_for(blocks: list[Block], index: int, default: str) -> str:
    """The cmake block after cpp block `index` on its page, before the next cpp block."""
    for b in blocks[index + 1:]:
        if b.language == "cpp":
            break
        if b.language == "cmake":
            return b.text
    return default


def check(root: Path, build: Path, only: str | None, list_only: bool) -> int:
    all_blocks = {p: blocks_of(p) for p in pages(root) if p.is_file()}
    readme = all_blocks.get(root / "README.md", [])
    default_cmake = next((b.text for b in readme if b.language == "cmake"), "")
    default_program = next((b.text for b in readme if b.language == "cpp" and "int main" in b.text),
                           "")
    problems, ran, skipped = 0, 0, 0
    with tempfile.TemporaryDirectory(prefix="pdd-doc-examples-") as tmp:
        runner = Runner(root, build, Path(tmp))
        if not list_only:  # the programs build side by side (each takes a core for a minute)
            runner.prebuild(programs_of(all_blocks, root, only, default_cmake, default_program))
        for page, blocks in all_blocks.items():
            for i, b in enumerate(blocks):
                if not b.language or (only and only not in b.where(root)):
                    continue
                if b.not_run:
                    skipped += 1
                    print(f"{b.where(root)}: not run ({b.not_run})")
                    continue
                if b.language == "cpp" and "int main" not in b.text:
                    print(f"{b.where(root)}: a cpp block without int main and without "
                          f"'<!-- example not run: REASON -->' before it")
                    problems += 1
                    continue
                if list_only:
                    print(f"{b.where(root)}: {b.language}")
                    continue
                t0 = time.monotonic()
                if b.language == "sh":
                    failure = runner.shell(b.text)
                elif b.language == "python":
                    failure = runner.python(b.text)
                elif b.language == "cpp":
                    failure = runner.program(b.text, cmake_for(blocks, i, default_cmake))
                else:  # cmake: the program before it on the page, else README's
                    source = next((c.text for c in reversed(blocks[:i])
                                   if c.language == "cpp" and "int main" in c.text),
                                  default_program)
                    failure = runner.program(source, b.text)
                ran += 1
                status = "FAILED " + failure if failure else "ok"
                print(f"{b.where(root)}: {b.language} {status} ({time.monotonic() - t0:.1f} s)",
                      flush=True)
                problems += failure is not None
    print(f"doc examples: {ran} run, {skipped} not run (with a reason), {problems} problems")
    return 1 if problems else 0


SELF_TEST_README = """# A page
```sh
echo this one passes
```
<!-- example not run: a reason -->
```sh
exit 3
```
```sh
echo planted failure; exit 7
```
```cpp
int f();
```
```
not an example
```
```python
print("passes")
```
"""


def self_test() -> int:
    """A page with one failing example and one cpp block without main or reason: 2 problems,
    reported at their lines; the example marked not run is not run."""
    with tempfile.TemporaryDirectory(prefix="pdd-doc-examples-self-test-") as tmp:
        root = Path(tmp)
        (root / "docs").mkdir()
        (root / "examples").mkdir()
        (root / "README.md").write_text(SELF_TEST_README)
        r = subprocess.run([sys.executable, __file__, str(root), "--root", str(root)],
                           capture_output=True, text=True)
    expected = ["README.md:9: sh FAILED exit 7", "README.md:12: a cpp block without int main",
                "README.md:6: not run (a reason)", "3 run, 1 not run (with a reason), 2 problems"]
    missing = [e for e in expected if e not in r.stdout]
    if r.returncode != 1 or missing or "this one passes" in r.stdout:
        print(f"self-test FAILED (exit {r.returncode}; missing {missing}):\n{r.stdout}")
        return 1
    print("self-test: planted failures reported at file:line")
    return 0


def main() -> int:
    if sys.argv[1:] == ["--self-test"]:
        return self_test()
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("build", type=Path, help="a configured and built build tree")
    parser.add_argument("--list", action="store_true", help="list the examples, run nothing")
    parser.add_argument("--only", help="only the examples whose file:line contains this")
    parser.add_argument("--root", type=Path, help="the repository (default: this script's)")
    a = parser.parse_args()
    root = (a.root or Path(__file__).resolve().parent.parent).resolve()
    return check(root, a.build.resolve(), a.only, a.list)


if __name__ == "__main__":
    sys.exit(main())
