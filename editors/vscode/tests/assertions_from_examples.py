#!/usr/bin/env python3
"""Writes a vscode-tmgrammar-test file for each example scene: the scene's lines, each followed
by assertions on what an independent reading (this script's small lexer) says the grammar must
find there: comments, strings, `let` and `macro` names, block kinds before `{`, builtin calls.
New and edited examples are covered without hand-written expectations.

usage: assertions_from_examples.py OUT_DIR EXAMPLE.rts...
"""
import json, os, re, sys

GRAMMAR = json.load(open(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "syntaxes", "rts.tmLanguage.json")))
BLOCKS = set(re.search(r"\(([a-z0-9_|]+)\)", GRAMMAR["repository"]["block"]["match"]).group(1).split("|"))
out_dir = sys.argv[1]
os.makedirs(out_dir, exist_ok=True)


def tokens(line, in_block_comment):
    """(column, length, scope) for what the grammar must find on this line, and whether a
    block comment is still open at its end."""
    found = []
    i = 0
    while i < len(line):
        if in_block_comment:
            end = line.find("*/", i)
            if end < 0:
                return found, True
            i = end + 2
            in_block_comment = False
            continue
        c = line[i]
        if line.startswith("//", i):
            found.append((i, 2, "comment.line.double-slash.rts"))
            break
        if line.startswith("/*", i):
            found.append((i, 2, "comment.block.rts"))
            in_block_comment = True
            i += 2
            continue
        if c == '"':
            j = i + 1
            while j < len(line) and line[j] != '"':
                j += 2 if line[j] == "\\" else 1
            found.append((i, 1, "string.quoted.double.rts"))
            i = j + 1
            continue
        m = re.match(r"[A-Za-z_][A-Za-z0-9_]*", line[i:])
        if m and (i == 0 or not (line[i - 1].isalnum() or line[i - 1] in "_.")):
            word = m.group(0)
            rest = line[i + len(word):]
            decl = re.match(r"\s+([A-Za-z_][A-Za-z0-9_]*)", rest)
            if word == "let" and decl:
                found.append((i + len(word) + decl.start(1), len(decl.group(1)), "variable.other.declaration.rts"))
            elif word == "macro" and decl:
                found.append((i + len(word) + decl.start(1), len(decl.group(1)), "entity.name.function.rts"))
            elif word in BLOCKS and re.match(r"\s*\{", rest):
                found.append((i, len(word), "support.class.block.rts"))
            i += len(word)
            if word in ("let", "macro") and decl:
                i += decl.end()
            continue
        i += 1
    return found, in_block_comment


for path in sys.argv[2:]:
    lines = open(path, encoding="utf-8").read().split("\n")
    out = ['// SYNTAX TEST "source.rts" "%s"' % os.path.basename(path)]
    in_block = False
    for line in lines:
        out.append(line)
        if "\t" in line or any(ord(ch) > 127 for ch in line):
            _, in_block = tokens(line, in_block)  # columns would not line up: no assertions
            continue
        found, in_block = tokens(line, in_block)
        for col, length, scope in found:
            if col < 2:
                out.append("// " + "<" + "-" * (length) + " " + scope if col == 0 else "//" + "^" * length + " " + scope)
            else:
                out.append("//" + " " * (col - 2) + "^" * length + " " + scope)
    with open(os.path.join(out_dir, os.path.basename(path)), "w", encoding="utf-8") as f:
        f.write("\n".join(out))
