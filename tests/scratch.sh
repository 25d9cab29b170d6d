# Sourced by the shell tests: fail(), refused(), a scratch folder that is removed on exit (with any
# tmpfs mounted in it unmounted first), and small tmpfs mounts that make a full disk to order.

fail() { echo "FAIL: $*"; exit 1; }

# refused REGEX ARGS...: "$bin" ARGS is a usage error whose one line matches REGEX, as "$expect"
# (expect_usage_error.sh) checks; a miss is printed and counted in $failures (the caller sets
# failures=0 first and fails at the end when it is not 0).
refused() {
  local regex=$1
  shift
  "$expect" "$regex" "$bin" "$@" >out.txt || { cat out.txt; failures=$((failures + 1)); }
  head -1 out.txt
}

scratch_mounts=()
scratch_folder=""
scratch_cleanup() {
  local m
  for m in "${scratch_mounts[@]}"; do mountpoint -q "$m" 2>/dev/null && umount "$m"; done
  [ -z "$scratch_folder" ] || rm -rf "$scratch_folder"
}
trap scratch_cleanup EXIT

# enter_scratch_folder [FOLDER]: cd into FOLDER (emptied first) or into a new temporary folder.
enter_scratch_folder() {
  if [ $# -gt 0 ]; then
    rm -rf "$1" && mkdir -p "$1" || fail "cannot create $1"
    cd "$1" || exit 1
  else
    scratch_folder=$(mktemp -d)
    cd "$scratch_folder" || exit 1
  fi
}

# mount_small_tmpfs FOLDER SIZE: a tmpfs of SIZE (e.g. 8k) at FOLDER, created if missing; status 1
# where the system does not allow mounting (the caller says so and skips its full-disk cases).
mount_small_tmpfs() {
  mkdir -p "$1" || return 1
  mountpoint -q "$1" 2>/dev/null && { umount "$1" || return 1; }
  mount -t tmpfs -o size="$2" tmpfs "$1" 2>/dev/null || return 1
  scratch_mounts+=("$(realpath "$1")")
}
