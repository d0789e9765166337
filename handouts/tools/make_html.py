#!/usr/bin/env python3
"""Renders every handout (handouts/*.md) to a self-contained HTML page with pandoc.

Usage: make_html.py --out DIR

Formulas become MathML (no script, no network) and figures are embedded, so each page is one
file that opens anywhere. Links to other handouts point to their pages; links to the kit's files
are rebased to DIR. Exits non-zero, naming the handout, if pandoc fails or warns (a formula it
cannot convert, a figure it cannot find).
"""
import argparse
import os
import re
import shutil
import subprocess
import sys

TOOLS = os.path.dirname(os.path.abspath(__file__))
HANDOUTS = os.path.dirname(TOOLS)


def handouts():
    """The handouts' Markdown files, in reading order."""
    return sorted(os.path.join(HANDOUTS, n) for n in os.listdir(HANDOUTS) if n.endswith(".md"))


def embed_option():
    """pandoc 2.19 and later say --embed-resources; 2.17 (Debian 12) only --self-contained."""
    help_text = subprocess.run(["pandoc", "--help"], capture_output=True, text=True).stdout
    return ["--embed-resources", "--standalone"] if "--embed-resources" in help_text \
        else ["--self-contained"]


def title(markdown_path):
    with open(markdown_path) as f:
        for line in f:
            if line.startswith("# "):
                return line[2:].strip()
    return os.path.basename(markdown_path)


def render(markdown_path, out_dir, embed):
    """Writes OUT_DIR/NAME.html; returns pandoc's warnings (empty when all went well)."""
    name = os.path.splitext(os.path.basename(markdown_path))[0]
    rebase = os.path.relpath(HANDOUTS, out_dir) + "/"
    run = subprocess.run(
        ["pandoc", markdown_path, "--from", "markdown+gfm_auto_identifiers", "--to", "html5",
         *embed, "--mathml", "--resource-path", HANDOUTS,
         "--css", os.path.join(TOOLS, "handout.css"),
         "--lua-filter", os.path.join(TOOLS, "links.lua"),
         "--metadata", "lang=en", "--metadata", f"pagetitle={title(markdown_path)}", "--metadata", f"rebase={rebase}",
         "--output", os.path.join(out_dir, name + ".html")],
        capture_output=True, text=True)
    problems = run.stderr.strip()
    if run.returncode != 0 and not problems:
        problems = f"pandoc exited with status {run.returncode}"
    # --self-contained is deprecated in newer pandoc: that notice is not a problem of the page.
    return "\n".join(l for l in problems.splitlines() if not re.search(r"deprecated", l))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--out", required=True, help="folder for the HTML pages")
    args = parser.parse_args()
    if not shutil.which("pandoc"):
        print("make_html: pandoc is needed (scripts/install-deps.sh installs it)", file=sys.stderr)
        return 1
    os.makedirs(args.out, exist_ok=True)
    embed = embed_option()
    failed = False
    for path in handouts():
        problems = render(path, os.path.abspath(args.out), embed)
        if problems:
            failed = True
            print(f"make_html: {os.path.relpath(path)}: {problems}", file=sys.stderr)
    print(f"make_html: {len(handouts())} pages in {args.out}")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
