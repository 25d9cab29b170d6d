#!/usr/bin/env bash
# Usage: empty_paths.sh MOLCHAOS EXPECT_USAGE_ERROR
# An empty file or folder name (or "-"), on the command line or in a --config file, is a usage error naming
# the option: where the option's default is "no such output", an empty value typed by hand (an
# unset shell variable) would otherwise drop that output without a word. (CTest cannot pass an
# empty argument, hence a script.)
set -u
bin=$(realpath "$1")
expect=$(realpath "$2")
. "$(dirname "$0")/../scratch.sh"
enter_scratch_folder
failures=0
message="empty name; give a path, or leave the option out$"
for flag in --out --checkpoint --restart --write-config --pair-correlations; do
  refused "^molchaos: error: $flag: $message" simulate --snapshot-times 1 "$flag" ""
done
if "$bin" simulate --help | grep -q -- --trajectory; then  # built with the HDF5 writer
  for flag in --trajectory --xyz; do
    refused "^molchaos: error: $flag: $message" simulate --snapshot-times 1 "$flag" ""
  done
fi
refused "^molchaos: error: --out: $message" sweep --out ""
refused "^molchaos: error: --out: $message" reproduce --out ""
refused "^molchaos: error: --cache: $message" reproduce --cache ""
refused "^molchaos: error: --out: $message" bench --theory --out ""
# "-" is standard input or output to other tools: refused rather than taken as a file name.
dash="'-' \\(standard input or output\\) is not supported; give a file or folder name$"
refused "^molchaos: error: --out: $dash" simulate --out -
refused "^molchaos: error: --restart: $dash" simulate --restart -
refused "^molchaos: error: --out: $dash" sweep --out -
refused "^molchaos: error: --out: $dash" reproduce --out -
printf 'checkpoint = ""\n' >empty.toml
refused "^molchaos: error: --config: empty.toml: key 'checkpoint': --checkpoint: $message" \
  simulate --config empty.toml
[ -z "$(ls -A | grep -v -e '^out\.txt$' -e '^empty\.toml$')" ] || fail "files written: $(ls -A)"
[ "$failures" -eq 0 ] || fail "$failures empty names not refused as such"
echo "ok: empty names and '-' refused, naming the option"
