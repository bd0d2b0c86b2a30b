#!/usr/bin/env python3
"""Checks the relative links of the project's markdown files.

Scans README.md, docs/*.md and docs/history/*.md (or the files given as arguments) for markdown
links, [text](path#anchor) and reference definitions ([name]: path#anchor), that are not URLs,
and checks that the path exists (relative to the file that links) and that the anchor names a
heading of the target file by GitHub's rules: the heading's text lowercased, every character but
letters, digits, spaces, '-' and '_' removed, spaces turned into '-', and a repeated anchor given
-1, -2, ... in the order the headings come. Links and headings inside fenced code blocks and
inline code spans are skipped.

Usage: python3 scripts/check_doc_links.py [FILE.md ...]
Prints each broken link as FILE:LINE: TARGET: why, then a summary; exits 1 if any is broken.
Python 3 standard library only.
"""

import glob
import os
import re
import sys
import unicodedata
import urllib.parse

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

FENCE = re.compile(r"^ {0,3}(`{3,}|~{3,})")
ATX = re.compile(r"^ {0,3}(#{1,6})(?:[ \t]+(.*?))?(?:[ \t]+#+)?[ \t]*$")
CODE_SPAN = re.compile(r"(`+)(.+?)\1")
INLINE_LINK = re.compile(r"!?\[((?:[^\[\]]|\[[^\[\]]*\])*)\]\(\s*<?([^)\s>]*)>?(?:\s+(?:\"[^\"]*\"|'[^']*'))?\s*\)")
REF_DEF = re.compile(r"^ {0,3}\[[^\]]+\]:\s*<?([^\s>]+)>?")
SCHEME = re.compile(r"^[a-zA-Z][a-zA-Z0-9+.-]*:")


def text_lines(lines):
    """Yields (number, line) for the lines outside fenced code blocks."""
    fence = None
    for number, line in enumerate(lines, 1):
        m = FENCE.match(line)
        if fence is None:
            if m:
                fence = m.group(1)
                continue
            yield number, line
        elif m and m.group(1)[0] == fence[0] and len(m.group(1)) >= len(fence) and \
                line.strip() == m.group(1):
            fence = None


def heading_text(raw):
    """The text GitHub renders for a heading's markdown (what its anchor is made from)."""
    parts = []
    pos = 0
    for m in CODE_SPAN.finditer(raw):
        parts.append(("md", raw[pos:m.start()]))
        parts.append(("code", m.group(2)))
        pos = m.end()
    parts.append(("md", raw[pos:]))
    out = []
    for kind, s in parts:
        if kind == "md":
            s = re.sub(r"!?\[([^\]]*)\]\([^)]*\)", r"\1", s)  # links and images: their text
            s = re.sub(r"<[^>]+>", "", s)  # inline HTML tags
            s = s.replace("*", "")  # emphasis
            s = re.sub(r"(?<!\w)_([^_]+)_(?!\w)", r"\1", s)  # _emphasis_ (a_b stays)
            s = s.replace("\\", "")
        out.append(s)
    return "".join(out).strip()


def slug(text):
    kept = []
    for c in text.lower():
        if c in " -_" or unicodedata.category(c)[0] in "LMN":
            kept.append(c)
    return "".join(kept).replace(" ", "-")


def anchors(path, cache={}):
    """The set of anchors of a markdown file's headings (github-slugger's duplicate rule)."""
    if path not in cache:
        with open(path, encoding="utf-8") as f:
            lines = f.read().split("\n")
        occurrences = {}
        for _, line in text_lines(lines):
            m = ATX.match(line)
            if not m:
                continue
            base = slug(heading_text(m.group(2) or ""))
            result = base
            while result in occurrences:
                occurrences[base] += 1
                result = f"{base}-{occurrences[base]}"
            occurrences[result] = 0
        cache[path] = set(occurrences)
    return cache[path]


def links(lines):
    """Yields (line number, target) for every link outside code."""
    for number, line in text_lines(lines):
        m = REF_DEF.match(line)
        if m:
            yield number, m.group(1)
            continue
        line = CODE_SPAN.sub(lambda t: " " * len(t.group(0)), line)
        for m in INLINE_LINK.finditer(line):
            yield number, m.group(2)


def check(path):
    """Returns (links checked, list of problems) for one markdown file."""
    with open(path, encoding="utf-8") as f:
        lines = f.read().split("\n")
    checked, problems = 0, []
    rel = os.path.relpath(path, ROOT)
    for number, target in links(lines):
        if not target or SCHEME.match(target) or target.startswith("//"):
            continue  # a URL (http:, mailto:, ...) or an empty link
        checked += 1
        file_part, _, anchor = target.partition("#")
        file_part = urllib.parse.unquote(file_part)
        anchor = urllib.parse.unquote(anchor)
        if file_part.startswith("/"):
            dest = os.path.join(ROOT, file_part.lstrip("/"))
        elif file_part:
            dest = os.path.normpath(os.path.join(os.path.dirname(path), file_part))
        else:
            dest = path
        if not os.path.exists(dest):
            problems.append(f"{rel}:{number}: {target}: no such file ({os.path.relpath(dest, ROOT)})")
            continue
        if not anchor:
            continue
        if not dest.endswith(".md") or os.path.isdir(dest):
            problems.append(f"{rel}:{number}: {target}: an anchor into a file that is not markdown")
            continue
        if anchor not in anchors(dest):
            problems.append(f"{rel}:{number}: {target}: no heading with the anchor #{anchor} in "
                            f"{os.path.relpath(dest, ROOT)}")
    return checked, problems


def main(argv):
    if argv:
        files = [os.path.abspath(a) for a in argv]
    else:
        files = [os.path.join(ROOT, "README.md")]
        files += sorted(glob.glob(os.path.join(ROOT, "docs", "*.md")))
        files += sorted(glob.glob(os.path.join(ROOT, "docs", "history", "*.md")))
        files = [f for f in files if os.path.exists(f)]
    total, problems = 0, []
    for path in files:
        checked, found = check(path)
        total += checked
        problems += found
    for p in problems:
        print(p)
    print(f"check_doc_links: {len(files)} files, {total} relative links, {len(problems)} broken")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
