"""Edits of a configuration's TOML text for the study scripts under bench/."""
import re


def set_key(text, section, key, value):
    """The config text with section.key = value: the key's line replaced, or
    the key added under the section's header (the section appended if absent)."""
    out, cur, done = [], None, False
    for ln in text.split("\n"):
        m = re.match(r"^\[([^\]]+)\]\s*$", ln)
        if m:
            cur = m.group(1)
        if cur == section and re.match(rf"^{re.escape(key)}\s*=", ln):
            ln, done = f"{key} = {value}", True
        out.append(ln)
    if not done:
        if f"[{section}]" in out:
            out.insert(out.index(f"[{section}]") + 1, f"{key} = {value}")
        else:
            out += [f"[{section}]", f"{key} = {value}"]
    return "\n".join(out)
