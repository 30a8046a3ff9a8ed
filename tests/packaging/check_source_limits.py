#!/usr/bin/env python3
"""The size limits of the code in src/: no file over 500 lines, no function over 100.

A function is a brace block that opens a function body: at the top level of a file (namespaces
aside) or directly inside a class or struct, its opening line not a type, namespace or
initializer. Lambdas and nested blocks count as part of the function they are in. Prints every
offender and exits 1 when there is one.
    check_source_limits.py SRC_DIR
"""
import os
import re
import sys

MAX_FILE_LINES = 500
MAX_FUNCTION_LINES = 100
TYPE_OPEN = re.compile(r'^\s*(template\s*<.*>\s*)?(class|struct|union|enum)\b[^;(]*\{\s*$|^\s*(class|struct|union|enum)\b[^;(]*$')
NAMESPACE_OPEN = re.compile(r'^\s*(namespace\b|extern\s+"C")')


def strip(line):
    line = re.sub(r'"(\\.|[^"\\])*"', '""', line)
    line = re.sub(r"'(\\.|[^'\\])*'", "''", line)
    return line.split('//')[0]


def functions(lines):
    """(first line, length) of each function body."""
    stack = []  # per open brace: 'namespace', 'type', 'function' or 'block'
    pending = []  # the text since the last ; { or } (what a brace opens)
    found = []
    in_comment = False
    for number, raw in enumerate(lines, 1):
        line = raw
        if in_comment:
            if '*/' not in line:
                continue
            line, in_comment = line.split('*/', 1)[1], False
        line = re.sub(r'/\*.*?\*/', '', strip(line))
        if '/*' in line:
            line, in_comment = line.split('/*', 1)[0], True
        if line.lstrip().startswith('#'):
            continue
        for ch in line:
            if ch == '{':
                head = ''.join(pending)
                if NAMESPACE_OPEN.search(head):
                    kind = 'namespace'
                elif re.search(r'\b(class|struct|union|enum)\b[^()]*$', head):
                    kind = 'type'
                elif all(k[0] in ('namespace', 'type') for k in stack) and ')' in head:
                    kind = 'function'
                else:
                    kind = 'block'
                stack.append((kind, number))
                pending = []
            elif ch == '}':
                if stack:
                    kind, start = stack.pop()
                    if kind == 'function':
                        found.append((start, number - start + 1))
                pending = []
            elif ch == ';':
                pending = []
            else:
                pending.append(ch)
        pending.append(' ')
    return found


def main(src):
    bad = []
    for root, _, files in os.walk(src):
        for name in sorted(files):
            if not name.endswith(('.cpp', '.h')):
                continue
            path = os.path.join(root, name)
            with open(path, encoding='utf-8') as f:
                lines = f.read().split('\n')
            rel = os.path.relpath(path, os.path.dirname(src))
            if len(lines) > MAX_FILE_LINES:
                bad.append(f'{rel}: {len(lines)} lines (at most {MAX_FILE_LINES})')
            for start, length in functions(lines):
                if length > MAX_FUNCTION_LINES:
                    bad.append(f'{rel}:{start}: a function of {length} lines (at most {MAX_FUNCTION_LINES})')
    for b in bad:
        print(b)
    print(f'source limits: {len(bad)} over')
    return 1 if bad else 0


if __name__ == '__main__':
    sys.exit(main(os.path.abspath(sys.argv[1])))
