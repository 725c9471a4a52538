#!/usr/bin/env python3
"""Checks the one-way layering of include/pdd (see include/pdd/README.md).

Every header under <root>/pdd belongs to a module: the first folder below pdd/ (core, madd,
io, ...), or, for a header directly in pdd/, its stem (errors.hpp: errors; pipeline.hpp belongs
to pipeline/ and may use pipeline/detail/). The table, a ```layering block in
<root>/pdd/README.md, gives each module a level. A header may include:
  - headers of its own module, and of modules on a strictly lower level;
  - a detail/ folder only from inside the folder that owns it (kernels/cgal/detail/ is private
    to kernels/cgal/).
Every include of pdd's own headers is written `#include <pdd/...>` (and the libraries' are
<...> too): a quoted include ("../mesh/merge.hpp", "detail/x.hpp", "pdd/core/point.hpp"), an
angle include with ".." or one without the pdd/ prefix that names a header under <root>/pdd
(<detail/x.hpp>) is reported; one that resolves to a header is then checked against the
levels too.
Anything else (an upward or sideways include, another module's detail/) is reported with
file:line, and the exit status is 1. `--self-test` builds a small bad tree in a temporary
folder and checks that each kind of violation is reported (the check can fail).
"""
import pathlib
import re
import sys
import tempfile

INCLUDE = re.compile(r'^\s*#\s*include\s*([<"])([^>"]+)[>"]')


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


def resolve(root, path, bracket, name):
    """The pdd/... path of the header an include names (None: not one of pdd's headers) and
    whether it is spelled as pdd requires (<pdd/...>, no "..")."""
    if bracket == "<" and name.startswith("pdd/") and ".." not in name.split("/"):
        return name, True
    bases = ([path.parent] if bracket == '"' else []) + [root, root / "pdd"]
    for base in bases:
        candidate = (base / name).resolve()
        if candidate.is_file() and (root / "pdd").resolve() in candidate.parents:
            return candidate.relative_to(root.resolve()).as_posix(), False
    # not found: a quoted include is pdd's own (its headers and the libraries' are all <...>),
    # and so is a relative path
    if bracket == '"' or ".." in name.split("/"):
        return (name if name.startswith("pdd/") else None), False
    return None, True


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
            bracket, name = m.groups()
            target, well_spelled = resolve(root, path, bracket, name)
            if not well_spelled:
                spelled = f'"{name}"' if bracket == '"' else f"<{name}>"
                problems.append(f"{rel}:{number}: includes {spelled}: pdd's headers are included "
                                f"as <pdd/...>" + (f" (<{target}>)" if target else ""))
            if target is None:
                continue
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
            # relative includes: only <pdd/...> names pdd's headers
            "pdd/core/rel.hpp": "#include \"../mesh/m.hpp\"\n#include \"b.hpp\"\n",
            "pdd/madd/own.hpp": "#include \"detail/d.hpp\"\n#include <core/b.hpp>\n",
            "pdd/io/y.hpp": "#include \"../gone.hpp\"\n#include \"third_party.h\"\n#include <vector>\n"
                            "#include <mpi.h>\n",
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
            "pdd/mesh/m.hpp:1: includes \"pdd/madd/side.hpp\": pdd's headers are included as",
            "pdd/core/rel.hpp:1: includes \"../mesh/m.hpp\": pdd's headers are included as "
            "<pdd/...> (<pdd/mesh/m.hpp>)",
            "pdd/core/rel.hpp:1: includes pdd/mesh/m.hpp: mesh (level 2) is not below core",
            "pdd/core/rel.hpp:2: includes \"b.hpp\": pdd's headers are included as <pdd/...> "
            "(<pdd/core/b.hpp>)",
            "pdd/madd/own.hpp:1: includes \"detail/d.hpp\": pdd's headers are included as "
            "<pdd/...> (<pdd/madd/detail/d.hpp>)",
            "pdd/madd/own.hpp:2: includes <core/b.hpp>: pdd's headers are included as <pdd/...> "
            "(<pdd/core/b.hpp>)",
            "pdd/io/y.hpp:1: includes \"../gone.hpp\": pdd's headers are included as <pdd/...>",
            "pdd/io/y.hpp:2: includes \"third_party.h\": pdd's headers are included as",
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
