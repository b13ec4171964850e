#!/usr/bin/env python3
"""No function of the project's C++ runs over 120 lines: split long ones along their phases.

Reads every .cpp and .h under src/ and export/, strips comments and string literals, and
follows braces: a brace opened after a closing parenthesis (a function's signature) at the
outermost function level starts a function body. Prints each function over the limit.
"""
import pathlib
import re
import sys

LIMIT = 120


def strip(text):
    text = re.sub(r'//[^\n]*', '', text)
    text = re.sub(r'/\*.*?\*/', lambda m: '\n' * m.group(0).count('\n'), text, flags=re.S)
    text = re.sub(r'R"\((.*?)\)"', lambda m: '""' + '\n' * m.group(1).count('\n'), text,
                  flags=re.S)
    text = re.sub(r'"(\\.|[^"\\\n])*"', '""', text)
    return re.sub(r"'(\\.|[^'\\\n])'", "''", text)


def long_functions(path):
    text = strip(path.read_text(encoding='utf-8'))
    stack, line, found = [], 1, []
    for i, ch in enumerate(text):
        if ch == '\n':
            line += 1
        elif ch == '{':
            k = i - 1
            while k >= 0 and text[k] not in ';{}':
                k -= 1
            head = text[k + 1:i].strip()
            last = head.split('\n')[-1].strip()
            is_fn = (re.search(r'\)\s*(const|override|noexcept|final|\s)*$', head) or
                     re.search(r'\)\s*->', head)) and not re.match(
                         r'^(if|for|while|switch|catch|else)\b', last)
            stack.append(('fn' if is_fn else 'block', line, head))
        elif ch == '}' and stack:
            kind, start, head = stack.pop()
            if kind == 'fn' and all(k != 'fn' for k, _, _ in stack) and line - start + 1 > LIMIT:
                found.append((line - start + 1, start, head.split('\n')[0][:80]))
    return found


def main():
    root = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else '.')
    bad = 0
    for folder in ('src', 'export'):
        for path in sorted((root / folder).rglob('*')):
            if path.suffix in ('.cpp', '.h'):
                for n, start, head in long_functions(path):
                    print(f'{path.relative_to(root)}:{start}: {n} lines: {head}')
                    bad += 1
    print(f'{bad} functions over {LIMIT} lines')
    return 1 if bad else 0


if __name__ == '__main__':
    sys.exit(main())
