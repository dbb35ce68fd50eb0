#!/usr/bin/env python3
"""Every relative link of README.md, CHANGELOG.md and docs/*.md points at a file of the
repository, and every #anchor at a heading of the target (GitHub's anchors: lower case,
punctuation dropped, spaces as hyphens). Prints each broken link; exit 1 if any.

  check_doc_links.py REPOSITORY_ROOT
"""
import os
import re
import sys


def anchors(path):
    found = set()
    in_code = False
    with open(path, encoding="utf-8") as f:
        for line in f:
            if line.startswith("```"):
                in_code = not in_code
            m = None if in_code else re.match(r"^#+\s+(.*)", line)
            if m:
                title = re.sub(r"[^\w\- ]", "", m.group(1).strip().lower())
                found.add(title.replace(" ", "-"))
    return found


def main(root):
    docs = os.path.join(root, "docs")
    files = [os.path.join(root, "README.md"), os.path.join(root, "CHANGELOG.md")]
    files += sorted(os.path.join(docs, f) for f in os.listdir(docs) if f.endswith(".md"))
    broken = 0
    for path in files:
        with open(path, encoding="utf-8") as f:
            text = f.read()
        for m in re.finditer(r"\]\(([^)\s]+)\)", text):
            link = m.group(1)
            if re.match(r"^[a-z]+:", link):
                continue  # https:, mailto:
            target, _, anchor = link.partition("#")
            target = os.path.normpath(os.path.join(os.path.dirname(path), target)) if target else path
            line = text.count("\n", 0, m.start()) + 1
            where = "%s:%d" % (os.path.relpath(path, root), line)
            if not os.path.exists(target):
                print("%s: %s: no such file" % (where, link))
                broken += 1
            elif anchor and target.endswith(".md") and anchor not in anchors(target):
                print("%s: %s: no heading with that anchor" % (where, link))
                broken += 1
    print("%d broken link(s) in %d files" % (broken, len(files)))
    return 1 if broken else 0


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit("usage: check_doc_links.py REPOSITORY_ROOT")
    sys.exit(main(sys.argv[1]))
