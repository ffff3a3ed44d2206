#!/usr/bin/env bash
# The commit a build or a result comes from: 12 hex digits, with "-dirty"
# when tracked files differ from it (untracked and ignored files do not
# count), or "unknown" outside a git checkout. Results name it in their
# JSON context (git_sha), so a figure measured on uncommitted code says so.
cd "$(dirname "$0")/.."
sha=$(git rev-parse --short=12 HEAD 2>/dev/null) || { echo unknown; exit 0; }
git update-index -q --refresh >/dev/null 2>&1
if git diff-index --quiet HEAD -- 2>/dev/null; then echo "$sha"; else echo "$sha-dirty"; fi
