#!/usr/bin/env bash
# Usage: concurrent_sweeps.sh MOLCHAOS
# Two sweeps started at once on one --cache folder both succeed with byte-identical summaries and
# tables: where both compute an entry, each writes its own temporary (host, PID and a random
# number in the name) and renames it into place, so either copy is valid. Each sweep runs in a
# PID namespace of its own where the system allows it (both may then have PID 1, and neither can
# see the other's PID): the cache cleaner must still leave the other's live temporaries alone (it
# removes only the suite's temporaries older than an hour).
set -u
bin=$(realpath "$1")
. "$(dirname "$0")/../scratch.sh"
enter_scratch_folder

isolate=()
if unshare --pid --fork true 2>/dev/null; then isolate=(unshare --pid --fork); fi
args=(sweep --particles 100 --density 0.05 --restitution 0.5 0.9 1.0 --seeds 6 --t-end-tau0 20
      --quiet --threads 2 --cache cache)
# A live temporary of a writer this process cannot see (fresh, its PID unknown here): kept.
mkdir cache
foreign=".0123456789abcdef.csv.molchaos-tmp.$(hostname | tr ./ __).999999999.0123456789abcdef"
touch "cache/$foreign"
for round in 1 2 3; do
  rm -f cache/*.csv
  "${isolate[@]}" "$bin" "${args[@]}" --out a.csv > a.txt 2> a.err & first=$!
  "${isolate[@]}" "$bin" "${args[@]}" --out b.csv > b.txt 2> b.err & second=$!
  wait $first; status_a=$?
  wait $second; status_b=$?
  [ "$status_a" -eq 0 ] && [ "$status_b" -eq 0 ] ||
    fail "round $round: exit statuses $status_a and $status_b: $(cat a.err b.err)"
  cmp -s a.csv b.csv || fail "round $round: the two summaries differ"
  cmp -s a.txt b.txt || fail "round $round: the two tables differ"
  [ "$(ls cache/*.csv | wc -l)" -eq 18 ] || fail "round $round: $(ls cache | wc -l) cache entries, 18 expected"
  [ -e "cache/$foreign" ] || fail "round $round: a live temporary of another writer was removed"
  leftovers=$(ls -A cache | grep -v '\.csv$' | grep -vF "$foreign" || true)
  [ -z "$leftovers" ] || fail "round $round: temporaries left behind: $leftovers"
done
# A third sweep reuses every entry and prints the same table.
"$bin" "${args[@]}" --out c.csv > c.txt 2> /dev/null || fail "sweep on the shared cache"
cmp -s a.txt c.txt || fail "the table from the cache differs"
echo "ok: two concurrent sweeps on one cache (${isolate[*]:-one PID namespace}) agree byte for byte"
