#!/usr/bin/env bash
# Usage: checkpoint_tampered.sh MOLCHAOS EXPECT_USAGE_ERROR
# A checkpoint whose state makes no sense but whose checksum holds (edited, the FNV-1a checksum
# recomputed) is refused with exit status 2 and a line naming what is wrong, and nothing is
# written: a run's wall time that is not finite, a position that is not finite or lies outside
# the box, a velocity changed behind the kinetic energy the engine carries, a particle moved onto
# another (out of the cell it is filed in), a broken link or a changed time in the event
# calendar, a clock's time unit of 0, -1 or half its value, the shuffle's random generator all
# zero, a neighbour list of dense spheres naming a particle that does not exist, a sample, the
# contact statistics or a snapshot holding a number that is not finite. The untouched files
# resume.
set -u
bin=$(realpath "$1")
expect=$(realpath "$2")
. "$(dirname "$0")/../scratch.sh"
enter_scratch_folder
args=(simulate --particles 400 --density 0.1 --restitution 0.9 --quiet)
"$bin" "${args[@]}" --t-end 20 --out a.csv --checkpoint ck --checkpoint-interval 5 2>/dev/null ||
  fail "run with checkpoints"
# tamper OUT WHAT [IN]: IN (ck) with particle 0's record edited (x, y, vx, vy as doubles), or its
# calendar entry or neighbour list, or the clock or the shuffle's generator, and the checksum
# recomputed.
tamper() {
  python3 - "$1" "$2" "${3:-ck}" <<'PY' || fail "tamper $2"
import re, struct, sys
out, what, source = sys.argv[1], sys.argv[2], sys.argv[3]
data = bytearray(open(source, "rb").read())
at = data.index(b"\n\n") + 2                      # the head ends with an empty line
size = struct.unpack_from("<Q", data, at)[0]
payload = at + 8
sample = int(re.search(rb"^layout = .* sample (\d+)( |$)", data[:at], re.M).group(1))
# The run's part (done, wall seconds, the samples, the snapshot count: no snapshots here), then
# the engine's, which opens with the record array's length (a record per particle and one that
# ends the cells' lists) and particle 0's record.
samples = struct.unpack_from("<Q", data, payload + 16)[0]
snapshots = payload + 16 + 8 + samples * sample   # their count, then each snapshot
engine = snapshots + 8
if struct.unpack_from("<Q", data, snapshots)[0] == 0:
    assert struct.unpack_from("<Q", data, engine)[0] == 401, "layout of the payload not understood"
    record = engine + 8
    # The record's size (the engine's layout): the particles' original indices follow the
    # records, opening with their count.
    stride = next(b for b in range(48, 257, 16)
                  if struct.unpack_from("<Q", data, record + 401 * b)[0] == 400)
    x, y, vx, vy = struct.unpack_from("<4d", data, record)
if what == "sample_nan":  # the first sample's temperature (its time, then its temperature)
    struct.pack_into("<d", data, payload + 24 + 8, float("nan"))
elif what == "snapshot_nan":  # the first snapshot (t, box, collisions, then its positions)
    assert struct.unpack_from("<Q", data, snapshots + 8 + 24)[0] == 800, "snapshot not understood"
    struct.pack_into("<d", data, snapshots + 8 + 32 + 8, float("nan"))
elif what == "nan":
    struct.pack_into("<d", data, record, float("nan"))
elif what == "outside":
    struct.pack_into("<d", data, record, 1e6)
elif what == "velocity":
    struct.pack_into("<d", data, record + 16, 2 * vx + 1)
elif what == "wall":
    struct.pack_into("<d", data, payload + 8, float("nan"))
elif what == "overlap":  # particle 1 (the next record) onto particle 0, at its time
    struct.pack_into("<2d", data, record + stride, x, y)
elif what.startswith("theta") or what in ("rng_zero", "contacts"):
    # The clock (internal time, its offset, its time unit theta: 3 doubles) lies just before the
    # kinetic energy the engine carries (the sum of the squared internal velocities, found by its
    # value); the collision and event counts and the shuffle's generator (4 words and a spare,
    # its size in the layout) follow it, then two counts (uint64) and the collision observer.
    u2 = sum(struct.unpack_from("<d", data, record + k * stride + off)[0] ** 2
             for k in range(400) for off in (16, 24))
    found = [k for k in range(record + 401 * stride, payload + size - 8)
             if abs(struct.unpack_from("<d", data, k)[0] - u2) <= 1e-9 * u2]
    assert len(found) == 1, "layout of the clock not understood"
    if what == "rng_zero":  # the all-zero state
        data[found[0] + 24:found[0] + 56] = bytes(32)
    elif what == "contacts":  # the contact statistics' sum of (g.e)^2, after their count and
        # two other sums
        rng = int(re.search(rb"^layout = .* rng (\d+)( |$)", data[:at], re.M).group(1))
        struct.pack_into("<d", data, found[0] + 24 + rng + 16 + 24, float("nan"))
    else:  # theta 0, -1 or halved
        theta = struct.unpack_from("<d", data, found[0] - 8)[0]
        new = {"theta_zero": 0.0, "theta_negative": -1.0, "theta_half": theta / 2}[what]
        struct.pack_into("<d", data, found[0] - 8, new)
elif what == "list":  # dense spheres: particle 0's first neighbour made one far out of range.
    # The lists open with their count of particles (int32 400), the lines per list (int32) and
    # the number of 64-byte lines (uint64 400 * lines); list 0's count, then its first neighbour.
    found = [k for k in range(engine, payload + size - 16)
             if struct.unpack_from("<i", data, k)[0] == 400
             and 0 < struct.unpack_from("<i", data, k + 4)[0] <= 8
             and struct.unpack_from("<Q", data, k + 8)[0]
             == 400 * struct.unpack_from("<i", data, k + 4)[0]]
    assert len(found) == 1, "layout of the neighbour lists not understood"
    assert struct.unpack_from("<i", data, found[0] + 16)[0] > 0, "particle 0 has no neighbours"
    struct.pack_into("<i", data, found[0] + 20, 1000000)
else:  # particle 0's entry in the event calendar, found by its bucket count and mask (int64 B,
    # B - 1: 2048 buckets for 400 particles), then the current bucket, the cycle's start, the
    # filed count and the entries' count (400); an entry is its time, bucket, next and previous.
    buckets = data.index(struct.pack("<qq", 2048, 2047), engine)
    entry = buckets + 16 + 24 + 8
    assert struct.unpack_from("<Q", data, entry - 8)[0] == 400, \
        "layout of the calendar not understood"
    if what == "calendar_link":
        struct.pack_into("<i", data, entry + 12, 1000000)
    elif what == "calendar_time":  # a time a little later than its pending event's
        t = struct.unpack_from("<d", data, entry)[0]
        assert t < float("inf"), "particle 0 has no pending event"
        struct.pack_into("<d", data, entry, t * (1 + 1e-12))
h = 0xcbf29ce484222325  # FNV-1a of the head and the payload
for b in data[:payload + size]:
    h = ((h ^ b) * 0x100000001b3) & 0xFFFFFFFFFFFFFFFF
struct.pack_into("<Q", data, payload + size, h)
open(out, "wb").write(data)
PY
}
failures=0
refused_restart() {  # refused_restart REGEX FILE: resuming from FILE is a usage error matching REGEX
  refused "$1" "${args[@]}" --t-end 30 --out b.csv --restart "$2"
}
tamper nan_position nan
refused_restart "--restart.*particle 0 has a position or velocity that is not finite" nan_position
tamper outside outside
refused_restart "--restart.*particle 0 lies outside the box" outside
tamper velocity velocity
refused_restart "--restart.*kinetic energy .* differs from the velocities'" velocity
tamper overlap overlap
refused_restart "--restart.*particle 1 lies outside the cell it is filed in" overlap
tamper wall wall
refused_restart "--restart.*wall time .* not a finite time >= 0" wall
tamper calendar_link calendar_link
refused_restart "--restart.*event calendar not filing each particle once" calendar_link
tamper calendar_time calendar_time
refused_restart "--restart.*particle 0 is filed in the event calendar at another time" calendar_time
tamper theta_zero theta_zero  # ran for ever
refused_restart "--restart.*time unit theta not a finite number > 0" theta_zero
tamper theta_negative theta_negative  # ran on with time running backwards
refused_restart "--restart.*time unit theta not a finite number > 0" theta_negative
tamper theta_half theta_half
refused_restart "--restart.*engine's time .* lies before the time the run had reached" theta_half
# The paper's shuffle with its generator all zero (a run that never ended).
shuffled=(simulate --particles 400 --density 0.1 --restitution 0.9 --randomize paper --quiet)
"$bin" "${shuffled[@]}" --t-end 20 --out p.csv --checkpoint pk --checkpoint-interval 5 \
  2>/dev/null || fail "shuffled run with checkpoints"
tamper pk_rng rng_zero pk
refused "--restart.*random generator in the all-zero state" \
  "${shuffled[@]}" --t-end 30 --out b.csv --restart pk_rng
# The samples and contact statistics so far, and a snapshot, of a run that records them all.
recorded=(simulate --particles 400 --density 0.1 --restitution 0.9 --contacts --quiet)
"$bin" "${recorded[@]}" --t-end 20 --snapshot-times 2 --out r.csv --checkpoint rk \
  --checkpoint-interval 5 2>/dev/null || fail "run with contacts, a snapshot and checkpoints"
"$bin" "${recorded[@]}" --t-end 20 --out s.csv --checkpoint sk --checkpoint-interval 5 \
  2>/dev/null || fail "run with contacts and checkpoints"
tamper rk_snapshot snapshot_nan rk
refused "--restart.*snapshot at t = 2 not of N particles with finite values" \
  "${recorded[@]}" --t-end 30 --snapshot-times 2 --out b.csv --restart rk_snapshot
tamper sk_sample sample_nan sk
refused "--restart.*sample at t = 0 not finite" \
  "${recorded[@]}" --t-end 30 --out b.csv --restart sk_sample
tamper sk_contacts contacts sk
refused "--restart.*collision observer's sums not finite" \
  "${recorded[@]}" --t-end 30 --out b.csv --restart sk_contacts
# Dense spheres (neighbour lists): the first neighbour of particle 0 made one far out of range.
dense=(simulate --dim 3 --particles 400 --density 0.7 --restitution 0.9 --quiet)
"$bin" "${dense[@]}" --t-end 2 --out d.csv --checkpoint dk --checkpoint-interval 1 2>/dev/null ||
  fail "dense run with checkpoints"
tamper dk_list list dk
refused "--restart.*neighbour lists .* out of range" \
  "${dense[@]}" --t-end 3 --out b.csv --restart dk_list
[ ! -e b.csv ] || fail "an output written by a refused restart"
"$bin" "${dense[@]}" --t-end 3 --out e.csv --restart dk 2>/dev/null ||
  fail "the untouched dense checkpoint"
"$bin" "${args[@]}" --t-end 30 --out c.csv --restart ck 2>/dev/null ||
  fail "the untouched checkpoint"
"$bin" "${recorded[@]}" --t-end 30 --snapshot-times 2 --out c.csv --restart rk 2>/dev/null ||
  fail "the untouched checkpoint with contacts and a snapshot"
[ "$failures" -eq 0 ] || fail "$failures tampered checkpoints not refused as such"
echo "ok: every tampered checkpoint refused, naming what is wrong"
