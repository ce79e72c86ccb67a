#!/usr/bin/env python3
"""Which module of the library includes which (docs/design/architecture.md).

Prints one line per module of src/signorini/ and include/signorini/: the modules it includes and
how many #include lines name each. tests/core/layering_test.cpp checks the same edges against the
layers.
"""
import collections
import pathlib
import re

ROOT = pathlib.Path(__file__).resolve().parent.parent
INCLUDE = re.compile(r'\s*#\s*include\s*[<"]signorini/([a-z_]+)/[^">]+[">]')


def main() -> None:
    modules = sorted(p.name for p in (ROOT / "src/signorini").iterdir() if p.is_dir())
    edges = collections.defaultdict(collections.Counter)
    for base in (ROOT / "src/signorini", ROOT / "include/signorini"):
        for path in base.rglob("*"):
            if not path.is_file() or path.parent == base:
                continue
            module = path.relative_to(base).parts[0]
            for line in path.read_text(errors="ignore").splitlines():
                m = INCLUDE.match(line)
                if m and m.group(1) != module and m.group(1) in modules:
                    edges[module][m.group(1)] += 1
    for module in modules:
        targets = ", ".join(f"{t}({n})" for t, n in sorted(edges[module].items()))
        print(f"{module:10s} -> {targets}")


if __name__ == "__main__":
    main()
