#!/usr/bin/env bash
# The commit a build or a result comes from: 12 hex digits, with "-dirty"
# when tracked files that go into the binaries differ from it, or "unknown"
# outside a git checkout. Untracked and ignored files do not count, nor do
# edits under plots/, results/ or tests/python/ or to Markdown, which
# change no measured code. Results name it in their JSON context (git_sha),
# so a figure measured on uncommitted code says so.
cd "$(dirname "$0")/.."
sha=$(git rev-parse --short=12 HEAD 2>/dev/null) || { echo unknown; exit 0; }
git update-index -q --refresh >/dev/null 2>&1
if git diff-index --quiet HEAD -- . ':!plots' ':!results' ':!tests/python' ':!*.md' 2>/dev/null; then
  echo "$sha"
else
  echo "$sha-dirty"
fi
