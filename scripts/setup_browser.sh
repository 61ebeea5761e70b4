#!/usr/bin/env bash
# What the browser tests need beyond Python packages:
# - Debian's Chromium (/usr/bin/chromium), driven by Playwright (Playwright's own browser download
#   cannot work on these machines);
# - npm, once, to fetch reveal.js and MathJax for the offline decks (`make slides`).
# Install what is missing when we are root; otherwise say exactly what to install (the tests that
# need it are then skipped, each with this reason).
set -uo pipefail
missing=()
[ -x /usr/bin/chromium ] || missing+=(chromium)
command -v npm >/dev/null || missing+=(npm)
[ ${#missing[@]} -eq 0 ] && exit 0
if [ "$(id -u)" = 0 ] && command -v apt-get >/dev/null; then
  echo "setup: installing Debian's ${missing[*]} for the browser tests (apt-get install ${missing[*]})"
  if ! (apt-get install -y -qq "${missing[@]}" >/dev/null 2>&1 || (apt-get update -qq && apt-get install -y -qq "${missing[@]}")); then
    echo "setup: apt-get install ${missing[*]} failed; the tests that need it will be skipped" >&2
  fi
else
  echo "setup: missing ${missing[*]} and we are not root; install with"
  echo "         sudo apt-get install ${missing[*]}"
  echo "       then run 'make test' again. The tests that need it are skipped until then."
fi
exit 0
