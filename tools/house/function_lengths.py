#!/usr/bin/python3
"""Functions longer than a limit in src/ (issue 58 item 5), counted on the clang-formatted sources:
a function definition is a line at column 0 that opens a brace and is not a namespace, class,
struct, enum, union or initialiser (`= {`), up to the matching brace at column 0; its length is
the lines between them. Key tables and option declarations are counted apart: a function whose
name says it declares keys or options (declare*, *_keys, *keys*, add_*_options, add_*_command, *_table, *_table_rows)
or whose body is mostly designated initialisers (`.key =`).
    tools/house/function_lengths.py [--limit 60] [--list] [ROOT]"""
import argparse
import os
import re

SKIP = re.compile(r"^(namespace|class|struct|enum|union|template\s*<[^>]*>\s*(class|struct))\b|=\s*\{$|^extern\b")
TABLE_NAME = re.compile(r"(declare|_keys\b|keys_|_options\b|options_|table_rows|declarations|^add_\w+_command$|_table$|::table$)")


def functions(path):
    lines = open(path, encoding="utf-8", errors="replace").read().split("\n")
    i = 0
    while i < len(lines):
        line = lines[i]
        if line and not line[0].isspace() and line.rstrip().endswith("{") and not SKIP.search(line.strip()) \
                and not line.startswith(("#", "//", "}")):
            start = i
            # the signature may span lines above: take the name from the first '(' on this or earlier lines
            head = line
            j = i
            while "(" not in head and j > 0 and lines[j - 1] and not lines[j - 1].startswith(("}", "#", "//")):
                j -= 1
                head = lines[j] + " " + head
            k = i + 1
            while k < len(lines) and not lines[k].startswith("}"):
                k += 1
            body = lines[start + 1:k]
            m = re.search(r"([A-Za-z_][A-Za-z_0-9:~<>]*)\s*\(", head)
            name = m.group(1) if m else head.strip()[:40]
            designated = sum(1 for b in body if re.match(r"\s*(\{\s*)?\.[a-z_]+\s*=", b))
            table = bool(TABLE_NAME.search(name)) or designated * 4 >= len(body) > 0
            yield name, start + 1, len(body), table
            i = k + 1
            continue
        i += 1


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("root", nargs="?", default=os.path.join(os.path.dirname(__file__), "..", "..", "src"))
    p.add_argument("--limit", type=int, default=60)
    p.add_argument("--list", action="store_true")
    a = p.parse_args()
    long, tables = [], []
    for d, _, files in os.walk(a.root):
        for f in files:
            if f.endswith((".cpp", ".hpp")):
                path = os.path.join(d, f)
                for name, line, n, table in functions(path):
                    if n > a.limit:
                        (tables if table else long).append((n, os.path.relpath(path, a.root), line, name))
    for n, path, line, name in sorted(long, reverse=True) if a.list else []:
        print(f"{n:4d}  {path}:{line}  {name}")
    print(f"functions over {a.limit} lines: {len(long)} (key tables and option declarations apart: {len(tables)})")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
