#!/usr/bin/env python3
"""Prints the files over MAX_FILE lines and the functions over MAX_FUNCTION lines in the given
folders (default: physics contact sim input), longest first, and exits 1 when there are any.

A function is a brace block at namespace or class level whose head (the text since the previous
';', '{' or '}') holds a parameter list: free functions, member functions defined in a class or
out of it, constructors, operators. Lambdas and blocks inside a function count toward it. Its
length runs from the first line of its head to its closing brace. Comments, strings and
character literals are skipped when braces are counted.

Usage: scripts/code_size.py [--max-function N] [--max-file N] [FOLDER ...]
"""
import argparse
import pathlib
import re
import sys

CONTAINER = re.compile(r'\b(namespace|class|struct|union|enum)\b[^()]*$|extern\s+"C"\s*$')
CONTROL = re.compile(r'^\s*(if|for|while|switch|catch|do|else|try)\b')


def strip(text):
    """The text with comments, strings and character literals blanked (newlines kept)."""
    out, i, n = [], 0, len(text)
    while i < n:
        c = text[i]
        if text.startswith('//', i):
            j = text.find('\n', i)
            j = n if j < 0 else j
            out.append(' ' * (j - i))
            i = j
        elif text.startswith('/*', i):
            j = text.find('*/', i + 2)
            j = n if j < 0 else j + 2
            out.append(re.sub(r'[^\n]', ' ', text[i:j]))
            i = j
        elif text.startswith('R"', i):
            m = re.match(r'R"([^(\s]*)\(', text[i:])
            if not m:
                out.append(c)
                i += 1
                continue
            end = ')' + m.group(1) + '"'
            j = text.find(end, i + m.end())
            j = n if j < 0 else j + len(end)
            out.append(re.sub(r'[^\n]', ' ', text[i:j]))
            i = j
        elif c in '"\'':
            j = i + 1
            while j < n and text[j] != c:
                j += 2 if text[j] == '\\' else 1
            j = min(j + 1, n)
            # A digit separator (1'000) is no character literal.
            if c == "'" and i > 0 and text[i - 1].isalnum():
                out.append(c)
                i += 1
                continue
            out.append(re.sub(r'[^\n]', ' ', text[i:j]))
            i = j
        else:
            out.append(c)
            i += 1
    return ''.join(out)


def functions(path):
    """(name, first line, last line) of each function defined in the file."""
    text = strip(path.read_text(errors='replace'))
    found = []
    stack = []  # per open brace: 'container', 'function' or 'block'
    head_start = 0  # where the current head began (after the last ; { })
    starts = []  # for each open function: (name, line of its head)
    line = 1
    line_at = []
    for i, c in enumerate(text):
        if c == '{':
            head = text[head_start:i]
            inside_function = 'function' in stack
            if inside_function:
                kind = 'block'
            elif CONTAINER.search(head.strip()) or head.strip().endswith('=') or not head.strip():
                kind = 'container' if CONTAINER.search(head.strip()) else 'block'
            elif '(' in head and not CONTROL.match(head):
                kind = 'function'
            else:
                kind = 'block'
            stack.append(kind)
            if kind == 'function':
                lead = len(head) - len(head.lstrip())
                first = line + 0
                first = text.count('\n', 0, head_start + lead) + 1
                name = re.findall(r'([~\w:]+(?:operator\S*)?)\s*\(', head)
                starts.append((name[0] if name else '?', first))
            head_start = i + 1
        elif c == '}':
            kind = stack.pop() if stack else 'block'
            if kind == 'function':
                name, first = starts.pop()
                found.append((name, first, text.count('\n', 0, i) + 1))
            head_start = i + 1
        elif c == ';':
            head_start = i + 1
        elif c == '\n':
            line += 1
    return found


def main():
    ap = argparse.ArgumentParser(description=__doc__.split('\n\n')[0])
    ap.add_argument('--max-function', type=int, default=80)
    ap.add_argument('--max-file', type=int, default=400)
    ap.add_argument('folders', nargs='*', default=['physics', 'contact', 'sim', 'input'])
    a = ap.parse_args()
    root = pathlib.Path(__file__).resolve().parent.parent
    long_files, long_functions = [], []
    for folder in a.folders:
        for p in sorted((root / folder).rglob('*')):
            if p.suffix not in ('.cpp', '.hpp', '.h', '.cc') or not p.is_file():
                continue
            rel = p.relative_to(root)
            n = p.read_text(errors='replace').count('\n')
            if n > a.max_file:
                long_files.append((n, str(rel)))
            for name, first, last in functions(p):
                if last - first + 1 > a.max_function:
                    long_functions.append((last - first + 1, f'{rel}:{first}', name))
    print(f'files over {a.max_file} lines: {len(long_files)}')
    for n, f in sorted(long_files, reverse=True):
        print(f'  {n:5d}  {f}')
    print(f'functions over {a.max_function} lines: {len(long_functions)}')
    for n, where, name in sorted(long_functions, reverse=True):
        print(f'  {n:5d}  {where}  {name}')
    return 1 if long_files or long_functions else 0


if __name__ == '__main__':
    sys.exit(main())
