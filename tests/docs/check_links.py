#!/usr/bin/env python3
"""Fails on any note to the project's developers (issues, sessions, "the lead") and on any reference in README.md or docs/ that a reader of the repository cannot follow:
a markdown link whose relative target does not exist or leaves the repository, any mention of
the project's private ../shared notes, a named .md page that is not in the repository, and a
path into the source tree (docs/, engine/, scripts/, ...) that does not exist."""
import pathlib
import re
import sys

root = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else ".").resolve()
files = [root / "README.md", *sorted((root / "docs").rglob("*.md"))]

# [text](target), ![alt](target), "[x]: target" definitions, HTML src/href.
link_patterns = [
    re.compile(r"!?\[[^\]]*\]\(\s*<?([^)\s>]+)>?(?:\s+\"[^\"]*\")?\s*\)"),
    re.compile(r"^\s*\[[^\]]+\]:\s*(\S+)", re.M),
    re.compile(r"""(?:src|href)\s*=\s*["']([^"']+)["']"""),
]
outside = re.compile(r"(?:\.\./)+shared\b|/work/|\bshared/(?:docs|paper)\b")
md_name = re.compile(r"(?<![\w/.-])((?:\.\./|\./)?(?:[\w.-]+/)*[\w-]+\.md)\b")
tree_dirs = "docs|engine|scripts|tests|python|examples|web|server|cli|bench|docker"
tree_path = re.compile(r"(?<![\w/.-])((?:%s)/[\w./-]*[\w-])" % tree_dirs)
code_span = re.compile(r"`[^`\n]+`")
# Notes to the project's own developers belong in commit messages, not in user docs.
colleague_note = re.compile(
    r"\b(?:[Ii]ssues? \d+|the issue(?:'s)?|[Tt]he lead\b|(?:development )?[Ss]essions? \d+|"
    r"the session's|engineers?\b|coordinator)")
fenced = re.compile(r"^```.*?^```", re.M | re.S)


def exists(md, path):
    """A path resolves from the page's folder or from the repository root."""
    for base in (md.parent, root):
        p = (base / path).resolve()
        if (p == root or root in p.parents) and (p.exists() or p.with_suffix("").exists()):
            return True
    return False


problems = []
for md in files:
    where = md.relative_to(root)
    text = md.read_text(encoding="utf-8")
    prose = fenced.sub("", text)
    for line_no, line in enumerate(text.splitlines(), 1):
        note = colleague_note.search(line)
        if note:
            problems.append(f"{where}:{line_no}: a note to developers (\"{note.group(0)}\"): {line.strip()[:100]}")
        if outside.search(line):
            problems.append(f"{where}:{line_no}: points outside the repository: {line.strip()[:100]}")
    for pattern in link_patterns:
        for target in pattern.findall(prose):
            if re.match(r"^[a-z][a-z0-9+.-]*:", target, re.I) or target.startswith("#"):
                continue  # http:, https:, mailto: and in-page anchors
            path = target.split("#", 1)[0].split("?", 1)[0]
            resolved = (md.parent / path).resolve()
            if root not in resolved.parents:
                problems.append(f"{where}: link {target} leaves the repository")
            elif not resolved.exists():
                problems.append(f"{where}: link {target}: no such file")
    for name in set(md_name.findall(prose)):
        if not exists(md, name) and not (root / "docs" / pathlib.Path(name).name).exists():
            problems.append(f"{where}: names {name}, which is not in the repository")
    # Source paths in code spans; a {a,b} or * pattern counts when its fixed prefix names files.
    for span in code_span.findall(prose):
        for path in set(tree_path.findall(span)):
            if not (exists(md, path.rstrip("./")) or any(root.glob(path.rstrip("./") + "*"))):
                problems.append(f"{where}: names {path}, which does not exist")

for p in sorted(set(problems)):
    print(p)
print(f"checked {len(files)} files: {len(set(problems))} problem(s)")
sys.exit(1 if problems else 0)
