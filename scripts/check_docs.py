#!/usr/bin/env python3
"""Checks pdd's Markdown documentation (issue 38). Standard library only.

For README.md, CONTRIBUTING.md and every docs/**/*.md under ROOT (default: this repository):
  * every relative link and image target exists;
  * every `#anchor` into a .md page (or into the page itself) matches one of its headings,
    slugged as GitHub does;
  * every `benchmarks/results/...` path quoted in backticks exists (the figures' sources);
  * every link is on one line (a link split across lines would go unchecked);
  * README.md has at most 250 lines;
  * every page under docs/ is in mkdocs.yml's nav, and every nav entry exists.
Each problem is printed as file:line: message; the exit code is 1 when there is one.

  python3 scripts/check_docs.py [ROOT]
  python3 scripts/check_docs.py --self-test   # plants each kind of problem, checks it is reported
"""
from __future__ import annotations

import re
import sys
import tempfile
import unicodedata
from pathlib import Path
from urllib.parse import unquote

README_MAX_LINES = 250
FENCE = re.compile(r"^\s*(```|~~~)")
HEADING = re.compile(r"^ {0,3}(#{1,6})\s+(.*?)\s*#*\s*$")
LINK = re.compile(r"!?\[(?:[^\[\]]|\[[^\]]*\])*\]\(\s*<?([^)\s>]+)>?(?:\s+\"[^\"]*\")?\s*\)")
CODE_SPAN = re.compile(r"(`+)(.+?)\1")
RESULTS_PATH = re.compile(r"^benchmarks/results/[A-Za-z0-9_.\-/]+$")
SCHEME = re.compile(r"^[A-Za-z][A-Za-z0-9+.\-]*:")
NAV_PAGE = re.compile(r"^\s*-\s*(?:[^:]*:\s*)?([^\s:#]+\.md)\s*$")


def doc_files(root: Path) -> list[Path]:
    files = [root / name for name in ("README.md", "CONTRIBUTING.md") if (root / name).is_file()]
    docs = root / "docs"
    if docs.is_dir():
        files += sorted(docs.rglob("*.md"))
    return files


def prose_lines(text: str):
    """(line number, line) outside fenced code blocks."""
    fenced = False
    for number, line in enumerate(text.split("\n"), 1):
        if FENCE.match(line):
            fenced = not fenced
            continue
        if not fenced:
            yield number, line


def slug(heading: str) -> str:
    """GitHub's anchor for a heading's text."""
    text = re.sub(r"!?\[([^\]]*)\]\([^)]*\)", r"\1", heading)  # links keep their text
    text = text.replace("`", "")
    text = re.sub(r"<[^>]+>", "", text)  # inline HTML
    text = text.strip().lower()
    kept = []
    for ch in text:
        category = unicodedata.category(ch)
        if ch in " -_" or category[0] in "LN" or category == "Mn":
            kept.append(ch)
    return "".join(kept).replace(" ", "-")


def anchors(path: Path, cache: dict[Path, set[str]]) -> set[str]:
    if path not in cache:
        seen: dict[str, int] = {}
        found = set()
        for _, line in prose_lines(path.read_text(encoding="utf-8")):
            match = HEADING.match(line)
            if not match:
                continue
            base = slug(match.group(2))
            count = seen.get(base, 0)
            seen[base] = count + 1
            found.add(base if count == 0 else f"{base}-{count}")
        cache[path] = found
    return cache[path]


def check_links(root: Path, path: Path, cache: dict[Path, set[str]]) -> list[str]:
    problems = []
    rel = path.relative_to(root)
    for number, line in prose_lines(path.read_text(encoding="utf-8")):
        for span in CODE_SPAN.finditer(line):
            quoted = span.group(2).strip()
            if RESULTS_PATH.match(quoted) and not (root / quoted).exists():
                problems.append(f"{rel}:{number}: figure source `{quoted}` does not exist")
        prose = CODE_SPAN.sub("", line)
        links = list(LINK.finditer(prose))
        if prose.count("](") > len(links):
            problems.append(f"{rel}:{number}: a link this checker cannot read (keep a link's "
                            f"text and target on one line)")
        for match in links:
            target = match.group(1)
            if SCHEME.match(target) or target.startswith("//"):
                continue
            file_part, _, anchor = target.partition("#")
            file_part = unquote(file_part)
            destination = (path.parent / file_part).resolve() if file_part else path
            if not destination.exists():
                problems.append(f"{rel}:{number}: broken link: {target} ({file_part} does not exist)")
                continue
            if anchor and destination.suffix == ".md" and destination.is_file():
                if unquote(anchor).lower() not in anchors(destination, cache):
                    problems.append(f"{rel}:{number}: broken anchor: {target} (no heading "
                                    f"#{anchor} in {destination.name})")
    return problems


def nav_pages(mkdocs: Path) -> list[tuple[int, str]]:
    pages = []
    in_nav = False
    for number, line in enumerate(mkdocs.read_text(encoding="utf-8").split("\n"), 1):
        if re.match(r"^nav\s*:", line):
            in_nav = True
            continue
        if in_nav and line and not line[0].isspace() and not line.startswith("-"):
            in_nav = False
        if in_nav:
            match = NAV_PAGE.match(line)
            if match:
                pages.append((number, match.group(1)))
    return pages


def check_nav(root: Path) -> list[str]:
    mkdocs = root / "mkdocs.yml"
    if not mkdocs.is_file():
        return ["mkdocs.yml:1: missing"]
    docs_dir = root / "docs"
    match = re.search(r"^docs_dir\s*:\s*(\S+)", mkdocs.read_text(encoding="utf-8"), re.M)
    if match:
        docs_dir = root / match.group(1)
    problems = []
    listed = set()
    for number, page in nav_pages(mkdocs):
        listed.add(page)
        if not (docs_dir / page).is_file():
            problems.append(f"mkdocs.yml:{number}: nav page {page} does not exist")
    for page in sorted(docs_dir.rglob("*.md")):
        name = page.relative_to(docs_dir).as_posix()
        if name not in listed:
            problems.append(f"{page.relative_to(root)}:1: not in mkdocs.yml's nav")
    return problems


def check(root: Path) -> list[str]:
    root = root.resolve()
    problems = []
    cache: dict[Path, set[str]] = {}
    for path in doc_files(root):
        problems += check_links(root, path, cache)
    readme = root / "README.md"
    if readme.is_file():
        lines = len(readme.read_text(encoding="utf-8").splitlines())
        if lines > README_MAX_LINES:
            problems.append(f"README.md:{lines}: {lines} lines, more than {README_MAX_LINES}")
    problems += check_nav(root)
    return problems


def self_test() -> int:
    good = {
        "README.md": "# Title\n\nSee [the guide](docs/guide.md#a-section-pdd-mesh) and "
                     "![a picture](docs/pic.png).\n",
        "CONTRIBUTING.md": "# Contributing\n\n[Back](README.md#title)\n",
        "docs/guide.md": "# Guide\n\n## A section: `pdd-mesh`\n\n[Home](index.md) "
                         "[here](#guide) `benchmarks/results/x.md`\n",
        "docs/index.md": "# Index\n\n[Guide](guide.md)\n```\n[not a link](nowhere.md)\n```\n",
        "docs/pic.png": "",
        "benchmarks/results/x.md": "# x\n",
        "mkdocs.yml": "site_name: t\ndocs_dir: docs\nnav:\n  - Home: index.md\n  - guide.md\n",
    }
    plants = {
        "broken link": ("docs/guide.md", "[gone](missing.md)\n", "broken link: missing.md"),
        "broken anchor": ("docs/index.md", "[bad](guide.md#no-such-heading)\n",
                          "broken anchor: guide.md#no-such-heading"),
        "missing nav page": ("docs/orphan.md", "# Orphan\n", "docs/orphan.md:1: not in mkdocs.yml"),
        "missing figure source": ("docs/guide.md", "`benchmarks/results/gone.md`\n",
                                  "figure source `benchmarks/results/gone.md`"),
        "long README": ("README.md", "x\n" * README_MAX_LINES, "lines, more than"),
        "split link": ("docs/guide.md", "[a link\nsplit](guide.md)\n", "cannot read"),
    }
    failures = 0
    with tempfile.TemporaryDirectory() as tmp:
        base = Path(tmp)

        def write_tree(root: Path, extra: tuple[str, str] | None) -> None:
            for name, text in good.items():
                (root / name).parent.mkdir(parents=True, exist_ok=True)
                (root / name).write_text(text, encoding="utf-8")
            if extra:
                target = root / extra[0]
                target.parent.mkdir(parents=True, exist_ok=True)
                with target.open("a", encoding="utf-8") as f:
                    f.write(extra[1])

        clean = base / "clean"
        write_tree(clean, None)
        if check(clean):
            print("self-test: the clean tree reported:", *check(clean), sep="\n  ")
            failures += 1
        for kind, (name, text, expected) in plants.items():
            root = base / kind.replace(" ", "_")
            write_tree(root, (name, text))
            problems = check(root)
            if not any(expected in p for p in problems):
                print(f"self-test: the planted {kind} was not reported (got {problems})")
                failures += 1
            elif len(problems) != 1:
                print(f"self-test: the planted {kind} gave {len(problems)} problems: {problems}")
                failures += 1
    print("self-test:", "FAILED" if failures else f"passed ({len(plants)} planted problems reported)")
    return 1 if failures else 0


def main(argv: list[str]) -> int:
    if argv[1:] == ["--self-test"]:
        return self_test()
    if len(argv) > 2 or (len(argv) == 2 and argv[1].startswith("-")):
        print(__doc__.strip().split("\n\n")[-1], file=sys.stderr)
        return 2
    root = Path(argv[1]) if len(argv) == 2 else Path(__file__).resolve().parent.parent
    problems = check(root)
    for problem in problems:
        print(problem)
    pages = len(doc_files(root.resolve()))
    print(f"check_docs: {pages} pages, {len(problems)} problem(s)")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
