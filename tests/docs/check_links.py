#!/usr/bin/env python3
"""Checks that every relative link in the repository's Markdown files points at a file that
exists and, where it names an anchor (#...), at a heading of that file (GitHub's anchor rule:
lower case, backticks and punctuation other than '-' and '_' dropped, spaces to '-', a repeated
heading numbered -1, -2, ...).

Links are found in the text outside fenced code blocks (``` or ~~~) and inline code spans, and
may wrap over lines: [text](target) and [text](target "title"). Reference-style links, HTML
anchors and setext headings are not used in these docs and not checked."""
import functools
import pathlib
import re
import sys

root = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else ".").resolve()
link_re = re.compile(r"\[[^\]]*\]\(([^)\s]+)(?:\s+\"[^\"]*\")?\)")
fence_re = re.compile(r"^\s*(```|~~~)")
code_span_re = re.compile(r"`[^`\n]*`")


def prose_lines(md: pathlib.Path):
    """The file's lines with fenced blocks blanked (line numbers kept)."""
    out, fence = [], None
    for line in md.read_text(encoding="utf-8").splitlines():
        m = fence_re.match(line)
        if m and (fence is None or m.group(1) == fence):
            fence = m.group(1) if fence is None else None
            out.append("")
            continue
        out.append("" if fence else line)
    return out


@functools.lru_cache(maxsize=None)  # one read per linked file, not per link
def anchors(md: pathlib.Path):
    out, seen = set(), {}
    for line in prose_lines(md):
        if not line.startswith("#"):
            continue
        text = line.lstrip("#").strip()
        text = re.sub(r"\s+#+$", "", text)  # closing hashes
        text = re.sub(r"\[([^\]]*)\]\([^)]*\)", r"\1", text)  # a link in a heading keeps its text
        a = re.sub(r"[^\w\- ]", "", text.lower().replace("`", "")).replace(" ", "-")
        n = seen.get(a, 0)
        seen[a] = n + 1
        out.add(a if n == 0 else f"{a}-{n}")
    return out


bad, checked = [], 0
files = [p for p in root.rglob("*.md") if not any(part.startswith(("build", ".")) for part in p.relative_to(root).parts)]
for md in sorted(files):
    lines = prose_lines(md)
    text = "\n".join(code_span_re.sub(lambda m: " " * len(m.group(0)), line) for line in lines)
    for m in link_re.finditer(text):
        target = m.group(1)
        checked += 1
        no = text.count("\n", 0, m.start(1)) + 1
        if re.match(r"^[a-z]+:", target):
            continue  # http:, https:, mailto:
        path, _, frag = target.partition("#")
        dest = md if not path else (md.parent / path)
        if not dest.exists():
            bad.append(f"{md.relative_to(root)}:{no}: link to {target}: no file {dest}")
            continue
        if frag and dest.suffix == ".md" and frag not in anchors(dest):
            bad.append(f"{md.relative_to(root)}:{no}: link to {target}: no heading with anchor #{frag}")
for b in bad:
    print(b)
print(f"{len(files)} Markdown files, {checked} links, {len(bad)} broken", file=sys.stderr)
sys.exit(1 if bad else 0)
