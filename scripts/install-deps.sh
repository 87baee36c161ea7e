#!/usr/bin/env bash
# Installs the Debian packages cartan needs, and only those that are missing.
# Idempotent; safe to run on every `make`. Works as root on a fresh Debian 12 machine
# (uses sudo when not root and sudo is available).
#   bash scripts/install-deps.sh          the build and its tests (`make build`, `make run`)
#   bash scripts/install-deps.sh docs     also the documentation site and its browser test
#                                         (`make docs`, `make test`)
set -euo pipefail

packages=(
  build-essential cmake make pkg-config
  libeigen3-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  libcli11-dev nlohmann-json3-dev
  pybind11-dev python3-dev
  python3-numpy python3-scipy python3-matplotlib python3-pytest
  python3-distributed
  # `pip install --no-build-isolation .` (setup.py) into a venv; mypy and its stubtest for the stubs
  python3-venv python3-pip python3-setuptools python3-wheel python3-mypy
  clang libclang-rt-14-dev
)
# The documentation site (docs/site, scripts/build-docs.sh): Sphinx with MyST for the Markdown,
# Doxygen + Breathe for the C++ reference; its test (tests/site) drives Chromium by WebDriver.
# About 400 MB with Chromium, hence not part of `make build` / `make run`.
docs_packages=(
  python3-sphinx python3-sphinx-rtd-theme python3-myst-parser doxygen python3-breathe
  chromium chromium-driver python3-selenium
)
for group in "$@"; do
  case "$group" in
    docs) packages+=("${docs_packages[@]}") ;;
    *) echo "install-deps: unknown group '$group' (known: docs)" >&2; exit 2 ;;
  esac
done

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  exit 0
fi

echo "install-deps: installing ${missing[*]}" >&2
SUDO=""
if [ "$(id -u)" -ne 0 ]; then
  if command -v sudo >/dev/null 2>&1; then SUDO="sudo"; else
    echo "install-deps: missing packages (${missing[*]}) and not root; install them and retry" >&2
    exit 1
  fi
fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
