#!/usr/bin/env bash
# Create the virtual environment $2 with interpreter $1; on Debian, install python3-venv first if
# the interpreter lacks the venv module and we are root.
set -euo pipefail
python="$1"; venv="$2"
if [ -x "$venv/bin/python" ]; then exit 0; fi
if ! "$python" -c 'import venv, ensurepip' 2>/dev/null; then
  if [ "$(id -u)" = 0 ] && command -v apt-get >/dev/null; then
    apt-get update -qq && apt-get install -y -qq python3-venv
  else
    echo "make: $python has no venv/ensurepip module; install it (Debian: sudo apt-get install python3-venv)" >&2
    exit 1
  fi
fi
"$python" -m venv "$venv"
