#!/usr/bin/env bash
# Usage: sigint_resume.sh MOLCHAOS
# An interrupted sweep (SIGINT) leaves no partial result file; the next run resumes from the cache
# and its summary and cache files are byte-identical to an uninterrupted run's.
set -u
set -m  # job control: a background job must not start with SIGINT ignored
bin=$1
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
# 72 runs: several seconds even on a fast machine, while the interrupt comes as soon as the first run
# is cached (a fixed sleep let the whole sweep finish first on a faster machine).
args=(sweep --particles 2000 --density 0.05 --restitution 0.85,0.9,0.95 --randomize none,flux --seeds 12 --quiet --threads 2)
"$bin" "${args[@]}" --cache "$dir/ref" --out "$dir/ref.csv" >/dev/null || { echo "FAIL: reference sweep"; exit 1; }
total=$(ls "$dir/ref" | wc -l)

"$bin" "${args[@]}" --cache "$dir/int" --out "$dir/int.csv" >/dev/null 2>&1 &
pid=$!
cached() { ls "$dir/int" 2>/dev/null | grep -c '\.csv$'; }
for _ in $(seq 1200); do  # up to 60 s for the first cached run
  [ "$(cached)" -ge 1 ] && break
  kill -0 "$pid" 2>/dev/null || break
  sleep 0.05
done
kill -INT "$pid" || { echo "FAIL: the sweep ended before it could be interrupted"; exit 1; }
wait "$pid"
status=$?
echo "interrupted sweep exited with status $status"
[ ! -e "$dir/int.csv" ] || { echo "FAIL: summary written by an interrupted sweep"; exit 1; }
done_runs=$(cached)
echo "cache entries after the interrupt: $done_runs of $total"
for f in "$dir"/int/*.csv; do
  [ -e "$f" ] || continue
  cmp -s "$f" "$dir/ref/$(basename "$f")" || { echo "FAIL: cache entry $(basename "$f") differs from the reference"; exit 1; }
done

"$bin" "${args[@]}" --cache "$dir/int" --out "$dir/int.csv" >/dev/null || { echo "FAIL: resumed sweep"; exit 1; }
cmp "$dir/ref.csv" "$dir/int.csv" || { echo "FAIL: resumed summary differs"; exit 1; }
for f in "$dir"/ref/*.csv; do
  cmp -s "$f" "$dir/int/$(basename "$f")" || { echo "FAIL: cache entry $(basename "$f") differs after resume"; exit 1; }
done
leftover=$(ls "$dir/int" | grep -vc '\.csv$')
[ "$leftover" -eq 0 ] || { echo "FAIL: $leftover temporary files left in the cache"; exit 1; }
echo "ok: resumed sweep identical to the uninterrupted one ($total runs)"
