#!/usr/bin/env python3
"""Checks that every relative link in the repository's Markdown files points at a file that
exists and, where it names an anchor (#...), at a heading of that file (GitHub's anchor rule:
lower case, punctuation other than '-' and '_' dropped, spaces to '-')."""
import pathlib
import re
import sys

root = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else ".").resolve()
link_re = re.compile(r"\[[^\]]*\]\(([^)\s]+)\)")
fence_re = re.compile(r"^\s*```")


def anchors(md: pathlib.Path):
    out, seen, fenced = set(), {}, False
    for line in md.read_text(encoding="utf-8").splitlines():
        if fence_re.match(line):
            fenced = not fenced
            continue
        if fenced or not line.startswith("#"):
            continue
        text = line.lstrip("#").strip()
        text = re.sub(r"\[([^\]]*)\]\([^)]*\)", r"\1", text)  # a link in a heading keeps its text
        a = re.sub(r"[^\w\- ]", "", text.lower().replace("`", "")).replace(" ", "-")
        n = seen.get(a, 0)
        seen[a] = n + 1
        out.add(a if n == 0 else f"{a}-{n}")
    return out


bad = []
files = [p for p in root.rglob("*.md") if not any(part.startswith(("build", ".")) for part in p.relative_to(root).parts)]
for md in sorted(files):
    fenced = False
    for no, line in enumerate(md.read_text(encoding="utf-8").splitlines(), 1):
        if fence_re.match(line):
            fenced = not fenced
            continue
        if fenced:
            continue
        for target in link_re.findall(line):
            if re.match(r"^[a-z]+:", target):
                continue  # http:, https:, mailto:
            path, _, frag = target.partition("#")
            dest = md if not path else (md.parent / path)
            if not dest.exists():
                bad.append(f"{md.relative_to(root)}:{no}: link to {target}: no file {dest.relative_to(root) if dest.is_relative_to(root) else dest}")
                continue
            if frag and dest.suffix == ".md" and frag not in anchors(dest):
                bad.append(f"{md.relative_to(root)}:{no}: link to {target}: no heading with anchor #{frag}")
for b in bad:
    print(b)
print(f"{len(files)} Markdown files, {len(bad)} broken links", file=sys.stderr)
sys.exit(1 if bad else 0)
