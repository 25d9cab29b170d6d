# Sourced by the CLI test scripts: `bin`, the molchaos binary given as $1 (absolute), a scratch
# directory as the working directory (removed on exit), and fail MESSAGE.
set -u
bin=$(realpath "$1")
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
cd "$scratch" || exit 1
fail() { echo "FAIL: $*"; exit 1; }
