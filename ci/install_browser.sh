#!/usr/bin/env bash
# Install a headless browser for the report test (tests/test_report.py renders the HTML
# report with `chromium --headless`). Debian/Ubuntu: the `chromium` package. Run as root
# (CI containers) or with sudo. Idempotent: does nothing if chromium is already there.
set -euo pipefail
if command -v chromium >/dev/null 2>&1 || command -v chromium-browser >/dev/null 2>&1; then
  echo "install_browser: $(command -v chromium || command -v chromium-browser) already installed"
  exit 0
fi
SUDO=""
if [ "$(id -u)" -ne 0 ]; then
  SUDO="sudo"
fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update
$SUDO apt-get install -y --no-install-recommends chromium
chromium --version 2>/dev/null || true
