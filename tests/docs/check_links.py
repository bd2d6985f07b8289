#!/usr/bin/env python3
"""Every relative link in every Markdown file of the repository resolves: the file exists and,
for `page.md#anchor` or `#anchor`, the page has a heading with that anchor (GitHub's rule:
lower case, punctuation but '-' and '_' dropped, spaces to '-', repeats numbered -1, -2, ...).
Links inside code (fenced blocks, `spans`) are text, not links.

    check_links.py SOURCE_DIR
"""
import os
import re
import sys

SKIP_DIRS = {".git", "build", "build-sanitize", "node_modules", "__pycache__"}
LINK = re.compile(r"!?\[[^\]]*\]\(\s*<?([^)\s>]+)>?(?:\s+\"[^\"]*\")?\s*\)")
FENCE = re.compile(r"^\s*(```|~~~)")
HEADING = re.compile(r"^(#{1,6})\s+(.*?)\s*#*\s*$")


def prose_lines(text):
    """The lines outside fenced code blocks, with inline code spans blanked."""
    fenced = False
    for number, line in enumerate(text.split("\n"), 1):
        if FENCE.match(line):
            fenced = not fenced
            continue
        if not fenced:
            yield number, re.sub(r"`[^`]*`", "``", line)


def slug(heading):
    text = re.sub(r"!?\[([^\]]*)\]\([^)]*\)", r"\1", heading)  # a link's text only
    text = text.replace("`", "").lower()
    text = re.sub(r"[^\w\- ]", "", text)
    return text.replace(" ", "-")


def anchors(path, cache={}):
    if path not in cache:
        seen, found = {}, set()
        fenced = False
        for line in open(path, encoding="utf-8").read().split("\n"):
            if FENCE.match(line):
                fenced = not fenced
                continue
            m = None if fenced else HEADING.match(line)
            if m:
                base = slug(m.group(2))
                n = seen.get(base, 0)
                found.add(base if n == 0 else f"{base}-{n}")
                seen[base] = n + 1
        cache[path] = found
    return cache[path]


def main():
    root = os.path.abspath(sys.argv[1])
    pages, broken, checked = 0, [], 0
    for directory, subdirs, files in os.walk(root):
        subdirs[:] = sorted(d for d in subdirs if d not in SKIP_DIRS and not d.startswith("build"))
        for name in sorted(files):
            if not name.endswith(".md"):
                continue
            path = os.path.join(directory, name)
            pages += 1
            for number, line in prose_lines(open(path, encoding="utf-8").read()):
                for target in LINK.findall(line):
                    if re.match(r"^[a-z][a-z0-9+.-]*:", target):
                        continue  # http:, mailto: ...: not checked offline
                    checked += 1
                    file_part, _, anchor = target.partition("#")
                    where = f"{os.path.relpath(path, root)}:{number}: {target}"
                    linked = os.path.normpath(os.path.join(directory, file_part)) if file_part else path
                    if not os.path.exists(linked):
                        broken.append(f"{where}: no such file")
                    elif anchor and linked.endswith(".md") and anchor not in anchors(linked):
                        broken.append(f"{where}: no heading with anchor #{anchor}")
    print(f"{checked} relative links in {pages} Markdown files")
    for b in broken:
        print("BROKEN", b)
    return 1 if broken or checked == 0 else 0


if __name__ == "__main__":
    sys.exit(main())
