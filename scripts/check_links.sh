#!/usr/bin/env bash
# Checks the manual's links: every relative link of docs/*.md, README.md,
# CHANGELOG.md and datasets/README.md points at a file or folder that
# exists, and an anchor (FILE.md#anchor) at an explicit <a id="..."> or a
# heading of that file; every citation [n] is a link to entry n of
# docs/bibliography.md ([n](bibliography.md#n)), and that entry exists.
# A bibliography entry's own label (**[n]**), code blocks and `code spans`
# are left out. Exits 1 naming each broken link
# (FILE: target), 0 when every one resolves.
#   bash scripts/check_links.sh [ROOT]      (default: the repository root)
set -euo pipefail
ROOT=$(cd "${1:-$(dirname "$0")/..}" && pwd)
cd "$ROOT"

# The prose of a Markdown file: fenced code blocks and code spans removed.
prose() {
  awk '/^[ \t]*```/ { code = !code; next } !code' "$1" | sed 's/`[^`]*`//g'
}

# The anchors a Markdown file defines: explicit ids and heading slugs
# (lower case, punctuation other than - and _ dropped, spaces as -).
anchors() {
  grep -o '<a id="[^"]*"' "$1" | sed 's/<a id="//; s/"$//' || true
  prose "$1" | grep -E '^#{1,6} ' | sed -E 's/^#+ +//' |
    tr 'A-Z' 'a-z' | sed -E 's/[^a-z0-9 _-]//g; s/ /-/g' || true
}

failures=0
broken() {
  echo "$1: $2"
  failures=$((failures + 1))
}

files=$(ls docs/*.md README.md CHANGELOG.md datasets/README.md 2>/dev/null)
for f in $files; do
  dir=$(dirname "$f")
  text=$(prose "$f")
  # Links: ](target), the target up to the first ')' or space.
  while IFS= read -r target; do
    [ -z "$target" ] && continue
    case "$target" in
      http://* | https://* | mailto:*) continue ;;
    esac
    path=${target%%#*}
    anchor=""
    [[ "$target" == *"#"* ]] && anchor=${target#*#}
    if [ -z "$path" ]; then
      dest=$f
    else
      dest=$dir/$path
    fi
    if [ ! -e "$dest" ]; then
      broken "$f" "$target (no such file)"
      continue
    fi
    if [ -n "$anchor" ] && [[ "$dest" == *.md ]]; then
      anchors "$dest" | grep -qxF -- "$anchor" || broken "$f" "$target (no such anchor)"
    fi
  done < <(grep -o '](\([^) ]*\)' <<<"$text" | sed 's/^](//' || true)

  # Citations: a bracketed number must be a link to its bibliography entry.
  while IFS= read -r bare; do
    [ -n "$bare" ] && broken "$f" "citation $bare is not a link to docs/bibliography.md"
  done < <(sed -E 's/\*\*\[[0-9]+\]\*\*//g' <<<"$text" |
    grep -o -E '\[[0-9]{1,3}\]([^(]|$)' | grep -o -E '\[[0-9]+\]' || true)
  while IFS= read -r cite; do
    [ -z "$cite" ] && continue
    n=$(sed -E 's/^\[([0-9]+)\].*/\1/' <<<"$cite")
    a=$(sed -E 's/.*#([^)]*)\)$/\1/' <<<"$cite")
    case "$cite" in
      *"bibliography.md#"*) ;;
      *) broken "$f" "citation $cite does not point at docs/bibliography.md"; continue ;;
    esac
    [ "$n" = "$a" ] || broken "$f" "citation $cite points at entry $a"
  done < <(grep -o -E '\[[0-9]{1,3}\]\([^)]*\)' <<<"$text" || true)
done

if [ $failures -ne 0 ]; then
  echo "check_links: $failures broken link(s) or citation(s)"
  exit 1
fi
echo "check_links: every link and citation in $(wc -w <<<"$files") files resolves"
