#!/usr/bin/env python3
"""Replaces one generated section of docs/performance.md (or appends it): the text between
`<!-- NAME:begin (written by SCRIPT) -->` and `<!-- NAME:end -->`, so each bench script
rewrites only its own figures.

    write_doc_section.py DOC NAME SCRIPT TEXT_FILE
"""
import sys


def main() -> None:
    doc, name, script, text_file = sys.argv[1:5]
    text = open(doc).read()
    begin, end = f"<!-- {name}:begin (written by {script}) -->", f"<!-- {name}:end -->"
    block = begin + "\n" + open(text_file).read().rstrip("\n") + "\n" + end
    if begin in text and end in text:
        text = text[:text.index(begin)] + block + text[text.index(end) + len(end):]
    else:
        text = text.rstrip("\n") + "\n\n" + block + "\n"
    open(doc, "w").write(text)


if __name__ == "__main__":
    main()
