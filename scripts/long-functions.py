#!/usr/bin/env python3
"""Lists the functions of the tracked C++ files that are longer than N lines (default 80).

Usage: python3 scripts/long-functions.py [N]

A heuristic, not a parser: a function is a block whose opening line, at indentation 0 or 2,
ends with '{' and has a parenthesis (namespaces, classes, enums and control statements are
skipped), and it ends at the first '}' at the same indentation. Good enough to keep the house
rule "no function over ~80 lines" (docs/ARCHITECTURE.md) visible.
"""
import re
import subprocess
import sys

SKIP = re.compile(r'^\s*(namespace|struct|class|enum|union|extern|if|for|while|switch|else|do|try)\b')


def long_functions(limit):
    files = subprocess.check_output(['git', 'ls-files', '*.cpp', '*.hpp'], text=True).split()
    found = []
    for path in files:
        with open(path, encoding='utf-8', errors='replace') as f:
            lines = f.read().split('\n')
        i = 0
        while i < len(lines):
            line = lines[i]
            m = re.match(r'^( *)\S', line)
            if (m and len(m.group(1)) <= 2 and line.rstrip().endswith('{') and not SKIP.match(line)
                    and ('(' in line or ')' in line) and not line.strip().startswith('//')
                    and '=' not in line.split('(')[0]):
                indent = m.group(1)
                j = i + 1
                while j < len(lines) and not re.match('^' + indent + r'\}', lines[j]):
                    j += 1
                if j - i + 1 > limit:
                    found.append((j - i + 1, path, i + 1, line.strip()[:90]))
                i = j
            i += 1
    return sorted(found, reverse=True)


if __name__ == '__main__':
    if len(sys.argv) > 2 or (len(sys.argv) == 2 and not sys.argv[1].isdigit()):
        print('usage: python3 scripts/long-functions.py [N]   (N: a line count, default 80)', file=sys.stderr)
        sys.exit(2)
    limit = int(sys.argv[1]) if len(sys.argv) > 1 else 80
    for n, path, line, head in long_functions(limit):
        print(f'{n:5d} {path}:{line} {head}')
