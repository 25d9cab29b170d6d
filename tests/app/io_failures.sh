#!/usr/bin/env bash
# Usage: io_failures.sh MOLCHAOS
# The I/O layer loses nothing and says so: a corrupted cache entry is reported and recomputed,
# unwritable or special outputs are refused (exit 2, naming the flag) before any work, snapshot
# paths stay next to --out, a cache that cannot take a run stops the sweep naming the folder, and
# a full disk (a small tmpfs, where mounting is allowed) or the file-size limit gives exit 1 with
# no file or temporary left behind, and a signal while a run's outputs are written waits until
# they are all in place; results on standard output that cannot be written there give exit 1.
set -u
bin=$(realpath "$1")
. "$(dirname "$0")/../scratch.sh"
enter_scratch_folder

# 1. Corrupted cache entry: one changed digit of a T value.
args=(sweep --particles 200 --density 0.05 --restitution 0.9 --seeds 2 --quiet --threads 1 --cache cache)
"$bin" "${args[@]}" > first.txt 2>/dev/null || fail "first sweep"
entry=$(ls cache/*.csv | head -1)
row=$(grep -n '^[0-9]' "$entry" | sed -n 10p | cut -d: -f1)
sed -i "${row}s/^\([^,]*\),\([0-9.]*\)\([0-9]\)/\1,\2X\3/; ${row}s/X0/1/; ${row}s/X[1-9]/0/" "$entry"
"$bin" "${args[@]}" > second.txt 2> second.err || fail "sweep after corruption exits non-zero"
grep -q "warning: cache entry .*checksum mismatch" second.err || fail "corrupted entry not reported: $(cat second.err)"
cmp -s first.txt second.txt || fail "corrupted entry changed the result"
sed -i '1s/.*/# cache_key = 0000000000000000/' "$entry"
"$bin" "${args[@]}" > third.txt 2> third.err || fail "sweep after key edit"
grep -q "stored under key" third.err || fail "wrong key not reported"
echo "ok: corrupted cache entries are reported and recomputed"

# 7. A cache entry that cannot be put in place (its name taken by a directory; needs no mount):
# the sweep stops, exit 1, naming the cache folder and the OS error; no run counted as failed.
mkdir blocked
for entry in cache/*.csv; do mkdir "blocked/$(basename "$entry")"; done
"$bin" sweep --particles 200 --density 0.05 --restitution 0.9 --seeds 2 --quiet --threads 1 \
  --cache blocked --out blocked.csv > /dev/null 2> err.txt
s=$?
[ "$s" -eq 1 ] || fail "blocked cache entries gave status $s: $(tail -n 1 err.txt)"
grep -Eq "^molchaos: failed: cannot store a run in the cache blocked: cannot write blocked/[0-9a-f]{16}\.csv: rename failed \(Is a directory\)$" err.txt ||
  fail "blocked cache entries not named: $(tail -n 1 err.txt)"
! grep -q "run(s) failed" err.txt || fail "blocked cache entries counted as failed runs"
[ ! -e blocked.csv ] || fail "a summary was written although the cache failed"
rm -rf blocked
echo "ok: a cache entry that cannot be put in place stops the sweep"

# 6. The cleaner removes only its own temporaries: not a user's file with ".tmp." in its name, not
# another writer's in-progress file.
touch cache/thesis.tmp.tex cache/run.csv.tmp.99999999 "cache/.x.csv.molchaos-tmp.otherhost.1.0123456789abcdef"
"$bin" "${args[@]}" > /dev/null 2>&1 || fail "sweep with foreign files in the cache"
for f in thesis.tmp.tex run.csv.tmp.99999999 .x.csv.molchaos-tmp.otherhost.1.0123456789abcdef; do
  [ -e "cache/$f" ] || fail "the cache cleaner deleted $f"
done
rm -f cache/thesis.tmp.tex cache/run.csv.tmp.99999999 cache/.x.csv.molchaos-tmp.*
echo "ok: the cleaner leaves other files alone"
# Temporaries of a killed writer are removed beside every output, the checkpoint's included; a
# name whose process id no process can have is not a writer's (it stopped the run with "stoi").
host=$(hostname | tr ./ __)
mkdir -p ckdir outdir
touch -d '2 days ago' "ckdir/.c.ckpt.molchaos-tmp.$host.4000000.0123456789abcdef" \
  "outdir/.o.csv.molchaos-tmp.$host.99999999999.0123456789abcdef"
"$bin" simulate --particles 100 --t-end 2 --relax 1 --quiet --out outdir/o.csv --checkpoint ckdir/c.ckpt \
  --checkpoint-interval 1 2>cleaner.err || fail "simulate beside stale temporaries: $(cat cleaner.err)"
[ -z "$(ls -A ckdir | grep molchaos-tmp || true)" ] || fail "a stale temporary beside the checkpoint stayed"
# A live writer of another user (kill() says EPERM) is alive: its temporary stays, however old.
if [ "$(id -u)" -eq 0 ] && command -v setpriv >/dev/null; then
  chmod 755 .  # the scratch folder is the owner's alone
  mkdir -m 777 shared
  sleep 60 & sleeper=$!
  touch -d '2 hours ago' "shared/.big.h5.molchaos-tmp.$host.$sleeper.0123456789abcdef"
  setpriv --reuid=65534 --regid=65534 --clear-groups \
    "$bin" simulate --particles 100 --t-end 1 --relax 1 --quiet --out shared/o.csv 2>other.err
  status=$?
  kill $sleeper
  [ "$status" -eq 0 ] || fail "simulate as another user: $(cat other.err)"
  [ -e "shared/.big.h5.molchaos-tmp.$host.$sleeper.0123456789abcdef" ] ||
    fail "the temporary of another user's live writer was removed"
  rm -rf shared
fi
echo "ok: the cleaner removes killed writers' temporaries beside every output"

# 3. Unwritable outputs fail before the work, exit 2 naming the flag.
expect2() {
  local flag=$1; shift
  "$bin" "$@" > /dev/null 2> err.txt; local s=$?
  [ "$s" -eq 2 ] && grep -q -- "$flag" err.txt || fail "'$*' gave status $s: $(cat err.txt)"
}
expect2 --out simulate --particles 100 --t-end 1 --out /proc/run.csv
expect2 --out simulate --particles 100 --t-end 1 --out /sys/run.csv
expect2 --out simulate --particles 100 --t-end 1 --out "$(printf 'x%.0s' $(seq 300)).csv"
expect2 --out simulate --particles 100 --t-end 1 --out "$(printf 'x%.0s' $(seq 252)).csv"
# A name of the file system's longest (255 bytes) runs, its temporary's name cut to fit, the cut
# at a character of a two-byte name; a snapshot name it implies that is longer is refused at once.
for name in "$(printf 'x%.0s' $(seq 251)).csv" "$(printf 'é%.0s' $(seq 125)).csv"; do
  "$bin" simulate --particles 100 --t-end 1 --relax 1 --quiet --out "$name" 2> err.txt ||
    fail "a name of 255 bytes refused: $(cat err.txt)"
  [ -s "$name" ] && [ -z "$(ls -A | grep molchaos-tmp)" ] || fail "the 255-byte run's file: $(ls -A)"
  rm "$name"
done
# A path near the longest one (PATH_MAX, 4096 bytes): its temporary's name is cut to fit it too.
deep=.; for _ in $(seq 20); do deep=$deep/$(printf 'd%.0s' $(seq 200)); done
mkdir -p "$deep"
"$bin" simulate --particles 100 --t-end 1 --relax 1 --quiet --out "$(realpath "$deep")/a_long_path.csv" 2> err.txt ||
  fail "a path of $(( ${#PWD} + ${#deep} + 16 )) bytes refused: $(cut -c 1-200 err.txt)"
rm -rf ./ddd*
expect2 --out simulate --particles 100 --t-end 1 --relax 1 --snapshot-times 0.5 \
  --out "$(printf 'x%.0s' $(seq 251)).csv"
grep -q "snapshot0.csv: its name is 265 bytes, the file system takes at most 255" err.txt ||
  fail "the over-long snapshot name not named: $(cat err.txt)"
[ -z "$(ls -A | grep '^xxx')" ] || fail "a refused run left a file: $(ls -A)"
expect2 --cache sweep --particles 200 --seeds 1 --quiet --cache /proc/cache
expect2 --out reproduce --quick --seeds 1 --no-figures --out /proc/reproduced
expect2 --cache reproduce --quick --seeds 1 --no-figures --out reproduced --cache /proc/cache
[ ! -e reproduced ] || fail "a refused reproduce --cache left its --out folder behind"
expect2 --out bench --theory --out /sys/bench
echo "ok: unwritable outputs refused before the work"

# 4. Special files are not replaced.
mkfifo fifo; ln -s target.csv link.csv
expect2 --out simulate --particles 100 --t-end 1 --out fifo
expect2 --out simulate --particles 100 --t-end 1 --out link.csv
expect2 --out simulate --particles 100 --t-end 1 --out /dev/null
[ -p fifo ] && [ -L link.csv ] || fail "a special file was replaced"
echo "ok: special files refused"

# 8. Snapshot paths stay next to --out.
mkdir data.v2 sub
"$bin" simulate --particles 100 --t-end 1 --relax 1 --snapshot-times 0.5 --quiet --out data.v2/run 2>/dev/null || fail "simulate data.v2/run"
[ -f data.v2/run.snapshot0.csv ] || fail "snapshot not in data.v2/: $(ls)"
(cd sub && "$bin" simulate --particles 100 --t-end 1 --relax 1 --snapshot-times 0.5 --quiet --out ../run 2>/dev/null) || fail "simulate ../run"
[ -f run.snapshot0.csv ] || fail "snapshot of ../run not at ./run.snapshot0.csv: $(ls -a)"
# A run that stops before its later snapshot times takes the earlier run's files there away.
# (The times comma separated here, as a sweep's lists are; as several arguments below.)
"$bin" simulate --particles 100 --t-end 30 --relax 1 --snapshot-times 0.5,25 --quiet --out stop.csv 2>/dev/null || fail "simulate stop.csv"
[ -f stop.snapshot1.csv ] && grep -qx "# snapshot_times = 0.5 25" stop.csv || fail "no snapshot 1 of stop.csv"
"$bin" simulate --particles 100 --t-end 30 --relax 1 --snapshot-times 0.5 25 --max-collisions 100 --quiet --out stop.csv 2>/dev/null || fail "simulate stop.csv, stopped early"
grep -q "stop_reason = max_collisions" stop.csv && [ -f stop.snapshot0.csv ] && [ ! -e stop.snapshot1.csv ] ||
  fail "the earlier run's snapshot at a time the new run did not reach stayed: $(ls stop*)"
"$bin" simulate --particles 100 --t-end 30 --relax 1 --snapshot-times 0.5,10,25 --quiet --out stop.csv 2>/dev/null || fail "simulate stop.csv, three snapshots"
rm stop.snapshot1.csv  # a gap in the replaced run's snapshots: the later one goes all the same
"$bin" simulate --particles 100 --t-end 30 --relax 1 --quiet --out stop.csv 2>/dev/null || fail "simulate stop.csv, no snapshots"
[ -z "$(ls stop.snapshot* 2>/dev/null)" ] || fail "an earlier run's snapshots stayed beside a run without: $(ls stop*)"
# Only the replaced run's snapshots go: not this run's other outputs named like snapshots, nor
# the snapshots of a run whose --out differs only in its extension (the same snapshot names).
"$bin" simulate --particles 100 --t-end 2 --relax 1 --snapshot-times 1 --quiet --out own.csv 2>/dev/null || fail "simulate own.csv"
"$bin" simulate --particles 100 --t-end 2 --relax 1 --snapshot-times 1 --quiet --out own.csv \
  --pair-correlations own.snapshot1.csv --write-config own.snapshot2.csv 2>/dev/null || fail "simulate own.csv again"
[ -s own.snapshot1.csv ] && [ -s own.snapshot2.csv ] || fail "the run removed its own outputs named like snapshots: $(ls own*)"
# (The pair-correlation table there goes first: --checkpoint refuses to replace a file that is no
# checkpoint.)
rm own.snapshot1.csv
"$bin" simulate --particles 100 --t-end 2 --relax 1 --quiet --out own.csv --checkpoint own.snapshot1.csv \
  --checkpoint-interval 1 2>/dev/null || fail "simulate own.csv with a checkpoint"
[ -s own.snapshot1.csv ] || fail "the run removed its own checkpoint named like a snapshot"
# ... nor the file this run read its options from: a snapshot of the run it replaces, re-run with
# fewer snapshot times.
"$bin" simulate --particles 100 --t-end 5 --relax 1 --snapshot-times 1 4 --quiet --out cfg.csv 2>/dev/null || fail "simulate cfg.csv"
"$bin" simulate --config cfg.snapshot1.csv --snapshot-times 1 --seed 2 --quiet --out cfg.csv 2>/dev/null ||
  fail "simulate --config cfg.snapshot1.csv --out cfg.csv"
grep -qx '# seed = 2' cfg.csv && [ -s cfg.snapshot1.csv ] && grep -qx '# seed = 1' cfg.snapshot1.csv ||
  fail "the run removed the --config file it read: $(ls cfg*)"
"$bin" simulate --particles 100 --t-end 2 --relax 1 --snapshot-times 0.5,1 --quiet --out ext.csv 2>/dev/null || fail "simulate ext.csv"
"$bin" simulate --particles 100 --t-end 2 --relax 1 --quiet --out ext.txt 2>/dev/null || fail "simulate ext.txt"
[ -f ext.snapshot0.csv ] && [ -f ext.snapshot1.csv ] || fail "a run of --out ext.txt removed the snapshots of ext.csv"
# ... nor overwrites them: a run with snapshots of its own there is refused before it runs.
"$bin" simulate --particles 100 --t-end 2 --relax 1 --seed 7 --snapshot-times 0.5 --quiet --out ext.txt \
  2>ext.err && fail "a run of --out ext.txt overwrote the snapshot of ext.csv"
grep -q -- "--out: ext.snapshot0.csv holds results of another run" ext.err ||
  fail "no refusal naming the other run's snapshot: $(cat ext.err)"
grep -qx '# seed = 1' ext.snapshot0.csv || fail "ext.csv's snapshot was changed"
# A run stopped before its first snapshot time keeps its outputs; the table has no rows, and says so.
# An XYZ file is frames only: none is written (an empty one could not be re-run), and an earlier
# run's file of that name is removed, not left beside this run's outputs.
echo "an earlier run's frames" >early.xyz
"$bin" simulate --particles 200 --t-end 50 --restitution 0.7 --relax 1 --max-collisions 10 --snapshot-times 40 \
  --pair-correlations early_g.csv --xyz early.xyz --quiet --out early.csv 2>early.err || fail "a run stopped early failed: $(cat early.err)"
[ -s early.csv ] && grep -q '^# no rows: the run stopped before its first snapshot time' early_g.csv ||
  fail "a run stopped before its snapshots lost its outputs: $(ls early*)"
grep -q '0 of the 1 snapshot times reached' early.err || fail "no note of the snapshots not reached: $(cat early.err)"
[ ! -e early.xyz ] || fail "an XYZ file without frames was left: $(wc -c <early.xyz) bytes"
grep -q 'no --xyz file written (an XYZ file holds frames only), the earlier early.xyz removed' early.err ||
  fail "no note of the XYZ file not written: $(cat early.err)"
echo "ok: snapshot paths"

# 9. A signal while the outputs are written: it waits until they are all in place, no temporary
# is left (before, the CSV was in place, the rest missing, a temporary half-written), and the
# command then ends by the signal, saying its outputs are complete: with a checkpoint file too
# (the signal came after the run, whose checkpoint would repeat it; before, exit 0 without a word).
snapshot_times=$(seq -s ' ' 0 0.05 1)
for checkpoint in "" "--checkpoint sig.ckpt"; do
  rm -f sig.csv sig.xyz sig.snapshot*.csv
  # shellcheck disable=SC2086
  "$bin" simulate --particles 20000 --density 0.1 --relax 0 --t-end 1 --quiet $checkpoint \
    --snapshot-times $snapshot_times --xyz sig.xyz --out sig.csv 2>sig.err &
  pid=$!
  # SIGTERM: a script's background job ignores SIGINT. The output phase is known by a temporary
  # with content (the checks of the outputs at the start make empty ones).
  for _ in $(seq 4000); do
    [ -n "$(find . -maxdepth 1 -name '.sig*molchaos-tmp*' -size +0 2>/dev/null)" ] && break
    kill -0 $pid 2>/dev/null || break
    sleep 0.002
  done
  kill -TERM $pid 2>/dev/null
  wait $pid
  status=$?
  [ -z "$(ls -A | grep molchaos-tmp || true)" ] || fail "temporaries left by SIGTERM: $(ls -A)"
  [ -e sig.csv ] && [ -e sig.xyz ] && [ "$(ls sig.snapshot*.csv | wc -l)" -eq 21 ] ||
    fail "SIGTERM while writing left an incomplete set: $(ls sig* 2>/dev/null)"
  [ "$status" -eq 143 ] && grep -qx 'simulate: stopped by SIGTERM once its outputs were complete' sig.err ||
    fail "SIGTERM while writing ($checkpoint): status $status, $(cat sig.err)"
done
echo "ok: a signal while the outputs are written"

# 2a. The file-size limit (ulimit -f, no mount needed): the writes fail as on a full disk (was:
# SIGXFSZ killed the program, status 153, with the temporaries of its outputs left behind).
mkdir limited
echo "an earlier run" >limited/run.csv
(ulimit -f 8 && exec "$bin" simulate --particles 2000 --t-end 1 --relax 1 --snapshot-times 1 --quiet \
  --out limited/run.csv) > /dev/null 2> err.txt
s=$?
[ "$s" -eq 1 ] || fail "file-size limit gave status $s: $(cat err.txt)"
grep -q "cannot write limited/run\.[a-z0-9.]*csv: .*File too large" err.txt || fail "file-size limit not named: $(cat err.txt)"
[ "$(cat limited/run.csv)" = "an earlier run" ] || fail "the file-size limit replaced the earlier run.csv"
[ "$(ls -A limited)" = run.csv ] || fail "left behind at the file-size limit: $(ls -A limited)"
if "$bin" simulate --help | grep -q -- --trajectory; then
  # Three frames of 6000 disks: each snapshot CSV (0.46 MB) below the limit, the trajectory
  # (0.6 MB) above it.
  (ulimit -f 500 && exec "$bin" simulate --particles 6000 --t-end 1 --relax 1 --snapshot-times 0,0.5,1 \
    --quiet --out limited/h5run.csv --trajectory limited/run.h5) > /dev/null 2> err.txt
  s=$?
  [ "$s" -eq 1 ] || fail "file-size limit (H5MD) gave status $s: $(tail -n 2 err.txt)"
  grep -q "cannot write limited/run.h5: .*File too large" err.txt || fail "file-size limit (H5MD) not named: $(tail -n 2 err.txt)"
  [ "$(ls -A limited)" = run.csv ] || fail "left behind at the file-size limit (H5MD): $(ls -A limited)"
fi
# A signal whose checkpoint cannot be written: exit 1, the message names the signal and that the
# run is lost (was: only the write error, as if no signal had come).
(ulimit -f 100 && exec timeout --preserve-status -s TERM 1.5 "$bin" simulate --particles 20000 \
  --restitution 1 --relax 2 --t-end 1e5 --checkpoint limited/big.ckpt --out limited/big.csv --quiet) \
  > /dev/null 2> err.txt
s=$?
[ "$s" -eq 1 ] || fail "a signal whose checkpoint failed gave status $s: $(cat err.txt)"
grep -q "stopped by SIGTERM, but its checkpoint could not be written (cannot write limited/big.ckpt: .*File too large)): the run since the last checkpoint is lost" err.txt ||
  fail "the signal not named beside the failed checkpoint: $(cat err.txt)"
[ "$(ls -A limited)" = run.csv ] || fail "left behind by the failed checkpoint: $(ls -A limited)"
echo "ok: file-size limit"

# 9. Results whose only copy is standard output (theory's tables, a sweep without --out) that
# cannot be written there: exit 1 and one line saying so (was: exit 0 and a cut or empty output).
into_full_device() {
  "$bin" "$@" >/dev/full 2>full.err
  local s=$?
  [ "$s" -eq 1 ] || fail "$* into a full device: status $s"
  grep -qx "molchaos: failed: cannot write standard output.*" full.err ||
    fail "$* into a full device said: $(cat full.err)"
}
if [ -w /dev/full ]; then
  into_full_device theory
  into_full_device theory --json
  into_full_device sweep --particles 100 --seeds 1 --cache '' --quiet
  echo "ok: standard output that cannot be written"
else
  echo "note: no /dev/full here; standard output into a full device not run"
fi

# 2. Full disk: exit 1, nothing half-written, no temporary left, the earlier run's file in place.
if mount_small_tmpfs small 64k; then
  for n in 2000 6000; do
    echo "an earlier run" >small/run.csv
    "$bin" simulate --particles $n --t-end 1 --relax 1 --snapshot-times 1 --quiet --out small/run.csv > /dev/null 2> err.txt
    s=$?
    [ "$s" -eq 1 ] || fail "full disk (N = $n) gave status $s"
    grep -q "No space left" err.txt || fail "full disk not named: $(cat err.txt)"
    [ "$(cat small/run.csv)" = "an earlier run" ] || fail "a full disk replaced the earlier run.csv"
    leftovers=$(ls -A small | grep -v '^run\.csv$' || true)
    [ -z "$leftovers" ] || fail "left behind on a full disk: $leftovers"
    rm -f small/*
  done
  if "$bin" simulate --help | grep -q -- --trajectory; then  # built with the HDF5 writer
    # The H5MD trajectory on a full disk: exit 1 naming it, no crash at exit (HDF5 wrote its
    # file itself, and a file it could not close crashed its clean-up), nothing left behind.
    "$bin" simulate --particles 6000 --t-end 1 --relax 1 --snapshot-times 0,1 --quiet --out h5run.csv \
      --trajectory small/run.h5 > /dev/null 2> err.txt
    s=$?
    [ "$s" -eq 1 ] || fail "full disk (H5MD) gave status $s: $(tail -n 2 err.txt)"
    grep -q "cannot write small/run.h5: .*No space left" err.txt || fail "full disk (H5MD) not named: $(tail -n 2 err.txt)"
    [ -z "$(ls -A small)" ] || fail "left behind on a full disk (H5MD): $(ls -A small)"
    [ ! -e run.csv ] || fail "the run's CSV was put in place although its trajectory failed"
  fi
  echo "ok: full disk"
  # A full cache disk: the sweep (and reproduce) stops with exit 1 naming the cache folder and
  # the reason, instead of counting runs as failed (which once surfaced in reproduce as
  # "Fig3Data.curves[0].t is empty"); no temporary left, no summary written.
  mount_small_tmpfs small 8k || fail "remount"
  "$bin" sweep --particles 200 --density 0.05 --restitution 0.9 --seeds 4 --quiet --threads 2 --cache small --out full.csv > /dev/null 2> err.txt
  s=$?
  [ "$s" -eq 1 ] || fail "full cache disk gave status $s: $(cat err.txt)"
  grep -q "cannot store a run in the cache small: .*No space left" err.txt || fail "full cache not named: $(cat err.txt)"
  [ ! -e full.csv ] || fail "a summary was written although the cache failed"
  [ -z "$(ls -A small | grep -v '\.csv$' || true)" ] || fail "temporaries left in the full cache: $(ls -A small)"
  "$bin" reproduce --quick --seeds 1 --threads 1 --no-figures --cache small --out rep > /dev/null 2> err.txt
  s=$?
  [ "$s" -eq 1 ] || fail "reproduce on a full cache disk gave status $s"
  grep -q "cannot store a run in the cache small: .*No space left" err.txt || fail "reproduce: full cache not named: $(tail -n 3 err.txt)"
  rm -f small/* small/.*.molchaos-tmp.* 2>/dev/null
  echo "ok: full cache disk"
  # A full disk while figures are rendered (as at the end of reproduce): exit 1 naming the file
  # gnuplot could not write and the space left; no temporary of the figure left behind.
  mount_small_tmpfs small 12k || fail "remount"
  "$bin" bench --simulation --particles 100 --work 1000 --threads 1 --out small > /dev/null 2> err.txt
  s=$?
  [ "$s" -eq 1 ] || fail "figures on a full disk gave status $s: $(tail -n 1 err.txt)"
  grep -Eq "gnuplot wrote no small/work_precision_simulation\.(png|pdf) \([0-9]+ bytes free in small\)$" err.txt ||
    fail "figures on a full disk: cause not named: $(tail -n 1 err.txt)"
  [ -z "$(ls -A small | grep molchaos-tmp || true)" ] || fail "figure temporaries left: $(ls -A small)"
  echo "ok: full disk while rendering figures"
else
  echo "note: cannot mount a tmpfs here; full-disk case not run"
fi
echo "ok: io failures"
