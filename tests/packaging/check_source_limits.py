#!/usr/bin/env python3
"""The size limits of the code in src/: no file over 500 lines, no function over 100; in
src/world/ (the orchestration, which should read as a list of stages) no function over 60, and
the World class at most 10 data members (one per stage or shared state).

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
MAX_WORLD_FUNCTION_LINES = 60
MAX_WORLD_MEMBERS = 10
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


def world_data_members(lines):
    """The data members declared at the top level of `class World { ... };` in world.h."""
    members, depth, inside = [], 0, False
    text = ''
    for raw in lines:
        line = strip(raw)
        if not inside:
            if re.match(r'^class World\b[^;]*\{', line):
                inside, depth = True, 1
            continue
        if depth == 1:
            text += line.strip() + ' '
        depth += line.count('{') - line.count('}')
        if depth <= 0:
            break
        if depth > 1:
            text = re.sub(r'[^;{}]*\{[^{}]*$', '', text)  # a nested body: not members
            continue
        while ';' in text:
            decl, text = text.split(';', 1)
            decl = re.sub(r'\{[^{}]*\}', '', decl)  # brace initializers
            decl = re.sub(r'.*\}', '', decl).strip()  # the end of a nested body or a function's
            decl = re.sub(r'^(public|private|protected):', '', decl).strip()
            if not decl or '(' in decl or re.match(r'^(class|struct|using|friend|template|static)\b', decl):
                continue
            decl = re.sub(r'=[^,]*', '', re.sub(r'<[^<>]*>', '', decl))  # template arguments, initializers
            members += [name.split()[-1] for name in decl.split(',')]  # `int a, b;` declares two
    return members


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
            limit = MAX_WORLD_FUNCTION_LINES if os.path.basename(root) == 'world' else MAX_FUNCTION_LINES
            for start, length in functions(lines):
                if length > limit:
                    bad.append(f'{rel}:{start}: a function of {length} lines (at most {limit})')
            if rel.endswith(os.path.join('world', 'world.h')):
                members = world_data_members(lines)
                if len(members) > MAX_WORLD_MEMBERS:
                    bad.append(f'{rel}: class World has {len(members)} data members (at most '
                               f'{MAX_WORLD_MEMBERS}): {", ".join(members)}')
    for b in bad:
        print(b)
    print(f'source limits: {len(bad)} over')
    return 1 if bad else 0


if __name__ == '__main__':
    sys.exit(main(os.path.abspath(sys.argv[1])))
