#!/usr/bin/python3
"""The source tree keeps the rules docs/architecture.md states ("The floors"):

- each folder of src/ includes only the folders the page's floor table lists for it, read from
  the page itself, so that the page and the code cannot drift apart;
- no header includes itself through others (the project's #include "folder/name.h" graph of
  headers has no cycle);
- no source file (src/, tests/, tools/) is longer than 600 lines.

    tests/check_layers.py SOURCE_DIR

Prints every break of a rule and exits 1, or exits 0 when there is none.
"""

import os
import re
import sys

MAX_LINES = 600
INCLUDE = re.compile(r'^\s*#\s*include\s+"([a-z_0-9]+)/([a-z_0-9]+\.h)"')
FLOOR = re.compile(r'^([a-z]+)\s*->\s*([a-z, ]*?)\s*(\(.*\))?$')


def floors(page):
    """The folder -> allowed folders table of the page's first code block after "## The floors"."""
    text = open(page, encoding='utf-8').read()
    section = text.split('## The floors', 1)[1]
    block = section.split('```', 2)[1]
    allowed = {}
    for line in block.strip().splitlines():
        m = FLOOR.match(line.strip())
        if not m:
            continue
        below = m.group(2)
        names = [] if below.startswith('(') else [w.strip() for w in below.split(',') if w.strip()]
        allowed[m.group(1)] = set(names)
    return allowed


def includes(path):
    with open(path, encoding='utf-8') as f:
        return [(n, m.group(1), m.group(2)) for n, line in enumerate(f, 1)
                for m in [INCLUDE.match(line)] if m]


def main(root):
    errors = []
    allowed = floors(os.path.join(root, 'docs', 'architecture.md'))
    src = os.path.join(root, 'src')
    headers = {}
    for folder in sorted(os.listdir(src)):
        if folder not in allowed:
            errors.append(f'src/{folder}: a folder docs/architecture.md\'s floor table does not list')
            continue
        for name in sorted(os.listdir(os.path.join(src, folder))):
            if not name.endswith(('.c', '.h')):
                continue
            rel = f'{folder}/{name}'
            if name.endswith('.h'):
                headers.setdefault(rel, [])
            for line, target, header in includes(os.path.join(src, folder, name)):
                if target != folder and target not in allowed[folder]:
                    errors.append(f'src/{rel}:{line}: includes {target}/{header}, but {folder} may '
                                  f'include only {", ".join(sorted(allowed[folder])) or "nothing"} '
                                  '(docs/architecture.md, "The floors")')
                if name.endswith('.h'):
                    headers[rel].append(f'{target}/{header}')

    # a cycle among headers: depth-first search with the path kept
    state = {}

    def visit(h, path):
        state[h] = 'open'
        for nxt in headers.get(h, []):
            if state.get(nxt) == 'open':
                cycle = path[path.index(nxt):] + [nxt]
                errors.append('include cycle: ' + ' -> '.join(cycle))
            elif nxt not in state:
                visit(nxt, path + [nxt])
        state[h] = 'done'

    for h in sorted(headers):
        if h not in state:
            visit(h, [h])

    for top in ('src', 'tests', 'tools'):
        for folder, _, names in os.walk(os.path.join(root, top)):
            for name in sorted(names):
                path = os.path.join(folder, name)
                if not (name.endswith(('.c', '.h', '.py', '.sh')) or
                        (top == 'tools' and os.access(path, os.X_OK))):
                    continue
                try:
                    with open(path, encoding='utf-8') as f:
                        lines = sum(1 for _ in f)
                except UnicodeDecodeError:
                    continue
                if lines > MAX_LINES:
                    errors.append(f'{os.path.relpath(path, root)}: {lines} lines, more than {MAX_LINES}')

    for e in errors:
        print(e)
    return 1 if errors else 0


if __name__ == '__main__':
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    sys.exit(main(sys.argv[1]))
