#!/usr/bin/env bash
# The browser tests drive Debian's Chromium (/usr/bin/chromium) with Playwright; Playwright's own
# browser download cannot work on these machines.  Install it when it is missing and we are root;
# otherwise say exactly what to install (the browser tests then skip, each with this reason).
set -uo pipefail
if [ -x /usr/bin/chromium ]; then
  exit 0
fi
if [ "$(id -u)" = 0 ] && command -v apt-get >/dev/null; then
  echo "setup: installing Debian's chromium for the browser tests (apt-get install chromium)"
  if ! (apt-get install -y -qq chromium >/dev/null 2>&1 || (apt-get update -qq && apt-get install -y -qq chromium)); then
    echo "setup: apt-get install chromium failed; the browser tests will be skipped" >&2
  fi
else
  echo "setup: /usr/bin/chromium is missing and we are not root; install it with"
  echo "         sudo apt-get install chromium"
  echo "       then run 'make test' again. The browser tests are skipped until then."
fi
exit 0
