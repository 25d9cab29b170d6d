#!/usr/bin/env bash
# Usage: config_files.sh MOLCHAOS EXPECT_USAGE_ERROR
# Input files: a run repeated from its own CSV header (simulate --config run.csv), from a snapshot's
# header (run.snapshot0.csv), from its H5MD and XYZ trajectories and from the TOML
# that --write-config wrote gives the same bytes (a file of another version with a note that the
# numbers may differ); flags override the file; every subcommand reads one; unknown keys and out-of-range values are usage errors naming the key and the allowed range.
set -u
bin=$(realpath "$1")
expect=$(realpath "$2")
. "$(dirname "$0")/../scratch.sh"
enter_scratch_folder
"$bin" simulate --dim 3 --particles 500 --density 0.2 --restitution 0.85 --randomize paper \
  --contacts --seed 11 --t-end 30 --snapshot-times 1 2.5 --tc 1e-4 --samples-per-decade 7 \
  --out run.csv --write-config run.toml --quiet 2>/dev/null || fail "first run"
"$bin" simulate --config run.csv --out again.csv --quiet 2>again.err || fail "run from run.csv"
cmp run.csv again.csv || fail "the run repeated from its CSV header differs"
! grep -q "^note:" again.err || fail "a note on a file of this very version: $(cat again.err)"
# A file of another version is re-run with a note that the numbers may differ.
sed 's/^# version = .*/# version = 0.0.1+other/' run.csv >other_version.csv
"$bin" simulate --config other_version.csv --out other.csv --quiet 2>other.err || fail "run from another version's file"
grep -q "^note: --config other_version.csv was written by molchaos 0.0.1+other; this is molchaos .*: the same parameters need not give the same numbers" other.err ||
  fail "no note on another version's file: $(cat other.err)"
cmp run.snapshot1.csv again.snapshot1.csv || fail "its snapshot differs"
"$bin" simulate --config run.snapshot0.csv --out from_snapshot.csv --quiet 2>/dev/null ||
  fail "run from run.snapshot0.csv"  # a snapshot names its run too
cmp run.csv from_snapshot.csv && cmp run.snapshot1.csv from_snapshot.snapshot1.csv ||
  fail "the run repeated from its snapshot's header differs"
"$bin" simulate --config run.toml --out toml.csv --quiet 2>/dev/null || fail "run from run.toml"
cmp run.csv toml.csv || fail "the run repeated from --write-config's TOML differs"
sed 's/^version = .*/version = "0.0.1+other"/' run.toml >other_version.toml
"$bin" simulate --config other_version.toml --out toml_other.csv --quiet 2>toml_other.err ||
  fail "run from another version's TOML"
grep -q "^note: --config other_version.toml was written by molchaos 0.0.1+other" toml_other.err ||
  fail "no note on another version's TOML: $(cat toml_other.err)"
sed 's/$/\r/' run.csv >crlf.csv  # the same file saved with Windows line ends
"$bin" simulate --config crlf.csv --out crlf_again.csv --quiet 2>/dev/null || fail "run from crlf.csv"
cmp run.csv crlf_again.csv || fail "the run repeated from its CSV with CRLF line ends differs"
{ printf '\xef\xbb\xbf'; cat run.csv; } >bom.csv  # saved with a UTF-8 byte order mark
"$bin" simulate --config bom.csv --out bom_again.csv --quiet 2>/dev/null || fail "run from bom.csv"
cmp run.csv bom_again.csv || fail "the run repeated from its CSV with a byte order mark differs"
{ printf '\xef\xbb\xbf'; cat run.toml; } >bom.toml
"$bin" simulate --config bom.toml --out bom_toml.csv --quiet 2>/dev/null || fail "run from bom.toml"
cmp run.csv bom_toml.csv || fail "the run repeated from its TOML with a byte order mark differs"
# A checkpoint's head names the run too.
"$bin" simulate --config run.csv --t-end 3 --out ckpt_run.csv --checkpoint run.ckpt \
  --checkpoint-interval 1 --quiet 2>/dev/null || fail "run with a checkpoint"
"$bin" simulate --config run.ckpt --out from_ckpt.csv --quiet 2>/dev/null || fail "run from run.ckpt"
cmp ckpt_run.csv from_ckpt.csv || fail "the run repeated from its checkpoint's head differs"
echo "ok: a run repeated from its CSV (LF, CRLF, byte order mark), its TOML and its checkpoint, byte for byte"
# A file is known by its content, whatever its name, and read once (a pipe can be read only once).
cp run.csv run.dat
"$bin" simulate --config run.dat --out dat_again.csv --quiet 2>/dev/null || fail "run from run.dat"
cmp run.csv dat_again.csv || fail "the run repeated from its header under another name differs"
"$bin" simulate --config /dev/stdin --out piped.csv --quiet <run.toml 2>/dev/null ||
  fail "run from a pipe"
cmp run.csv piped.csv || fail "the run repeated from its TOML through a pipe differs"
grep '^#' run.csv >header_only.txt  # a result header without its rows
"$bin" simulate --config header_only.txt --out header_again.csv --quiet 2>/dev/null ||
  fail "run from a header without rows"
cmp run.csv header_again.csv || fail "the run repeated from its header alone differs"
echo "ok: a result file known by its content; a file read through a pipe"
# Integers are decimal whatever their leading zeros (read with base 0, 050 would be octal 40),
# on the command line and in a file; -0 is 0.
printf 'seed = 010\n' >zeros.toml
"$bin" simulate --config zeros.toml --particles 050 --max-collisions 0100 --relax -0 --t-end 1 \
  --out zeros.csv --quiet 2>/dev/null || fail "run with leading zeros"
grep -qx "# particles = 50" zeros.csv && grep -qx "# seed = 10" zeros.csv &&
  grep -qx "# max_collisions = 100" zeros.csv &&
  grep -qx "# relax_collisions_per_particle = 0" zeros.csv || fail "leading zeros or -0 misread"
echo "ok: integers with leading zeros read as decimal, -0 as 0"
# TOML groups digits with underscores: particles = 1_000 is 1000 (it was refused as no integer).
printf 'particles = 1_00\nt_end = 1_0.5\n' >grouped.toml
"$bin" simulate --config grouped.toml --out grouped.csv --quiet 2>/dev/null || fail "run with 1_00"
grep -qx "# particles = 100" grouped.csv && grep -qx "# t_end = 10.5" grouped.csv ||
  fail "digits grouped with underscores misread"
echo "ok: digits grouped by underscores, as TOML writes them"
if "$bin" simulate --help | grep -q -- --trajectory; then  # built with the HDF5 writer
  # An H5MD trajectory carries the run's parameters (/parameters): the run repeats from it too.
  "$bin" simulate --config run.csv --out traj.csv --trajectory traj.h5 --xyz traj.xyz --quiet \
    2>/dev/null || fail "run with a trajectory"
  "$bin" simulate --config traj.h5 --out traj_again.csv --trajectory traj_again.h5 \
    --xyz traj_again.xyz --quiet 2>/dev/null || fail "run from traj.h5"
  cmp run.csv traj_again.csv && cmp traj.h5 traj_again.h5 && cmp traj.xyz traj_again.xyz ||
    fail "the run repeated from its H5MD trajectory differs"
  echo "ok: a run repeated from its H5MD trajectory, byte for byte"
  # And from its extended XYZ file, whose comment lines carry the parameters.
  "$bin" simulate --config traj.xyz --out xyz_again.csv --xyz xyz_again.xyz --quiet \
    2>/dev/null || fail "run from traj.xyz"
  cmp run.csv xyz_again.csv && cmp traj.xyz xyz_again.xyz ||
    fail "the run repeated from its XYZ file differs"
  echo "ok: a run repeated from its extended XYZ file, byte for byte"
  # Its comment lines name the version that wrote it, as a CSV header does.
  sed 's/ version=[^ ]*/ version=0.0.1+other/' traj.xyz >other_version.xyz
  "$bin" simulate --config other_version.xyz --out xyz_other.csv --quiet 2>xyz_other.err ||
    fail "run from another version's XYZ file"
  grep -q "^note: --config other_version.xyz was written by molchaos 0.0.1+other" xyz_other.err ||
    fail "no note on another version's XYZ file: $(cat xyz_other.err)"
fi
"$bin" simulate --config run.csv --seed 12 --t-end 20 --out other.csv --quiet 2>/dev/null ||
  fail "run with flags over the file"
grep -qx "# seed = 12" other.csv && grep -qx "# t_end = 20" other.csv &&
  grep -qx "# restitution = 0.85" other.csv || fail "flags do not override the file"
echo "ok: flags override the file"
cat >sweep.toml <<'TOML'
# a sweep from a file
density = [0.05, 0.1]      # two state points
randomize = ["none", "flux"]
particles = 300
seeds = 1
t-end-tau0 = 0.5
TOML
"$bin" sweep --config sweep.toml --cache cache --out sweep.csv --threads 1 >/dev/null 2>&1 ||
  fail "sweep from a file"
[ "$(grep -c '^0\.[05]*1*,' sweep.csv)" -eq 4 ] || fail "sweep.csv lacks the 4 state points"
"$bin" sweep --config sweep.csv --cache cache --out again.csv --threads 1 >/dev/null 2>&1 ||
  fail "sweep from its summary"
cmp sweep.csv again.csv || fail "the sweep repeated from its summary's header differs"
# An elastic sweep's header holds no cooling run length (which such a sweep refuses as given).
"$bin" sweep --particles 300 --seeds 2 --restitution 1 --t-end-elastic 5 --cache cache \
  --out elastic.csv --threads 1 >/dev/null 2>&1 || fail "elastic sweep"
grep -q '^# t_end_in_tau0' elastic.csv && fail "an elastic sweep's header names a cooling run length"
"$bin" sweep --config elastic.csv --cache cache --out elastic2.csv --threads 1 >/dev/null 2>&1 ||
  fail "elastic sweep from its summary"
cmp elastic.csv elastic2.csv || fail "the elastic sweep repeated from its summary's header differs"
printf 'restitution = 0.8\ndensity = 0.1\njson = true\n' >theory.toml
"$bin" theory --config theory.toml | grep -q '"restitution": 0.8' || fail "theory from a file"
printf 'simulation = true\nparticles = [100]\nwork = 1000\nthreads = 1\nout = "bench"\n' >bench.toml
"$bin" bench --config bench.toml >/dev/null 2>&1 || fail "bench from a file"
grep -q '^100,10,' bench/work_precision_simulation.csv || fail "bench did not take N and work from the file"
"$bin" bench --config bench.toml --work 2000 --out bench2 >/dev/null 2>&1 || fail "bench with flags over the file"
grep -q '^100,20,' bench2/work_precision_simulation.csv || fail "bench flags do not override the file"
"$bin" bench --config bench2/work_precision_simulation.csv --out bench3 >/dev/null 2>&1 ||
  fail "bench from its own result file"
# The same N, seeds, A and error (the CPU seconds differ from run to run).
cut -d, -f1,2,4,5 bench2/work_precision_simulation.csv | grep -v '^#' >bench2.rows
cut -d, -f1,2,4,5 bench3/work_precision_simulation.csv | grep -v '^#' >bench3.rows
cmp -s bench2.rows bench3.rows || fail "bench --config on its result file does not repeat the measurement"
echo "ok: sweep, theory and bench read their options from files; a sweep repeats from its summary"
# TOML's literal-quoted keys and its integers of base 16, 8 and 2 (with underscores) read as
# the same run's decimal values.
printf "'t_end' = 2\nseed = 0x1_0\nparticles = 0b1100_1000\nrelax = 0o12\n" >bases.toml
"$bin" simulate --config bases.toml --out bases.csv --quiet 2>/dev/null || fail "run from bases.toml"
"$bin" simulate --t-end 2 --seed 16 --particles 200 --relax 10 --out decimal.csv --quiet 2>/dev/null ||
  fail "the same run by flags"
cmp bases.csv decimal.csv || fail "a literal-quoted key or a 0x, 0o, 0b integer read otherwise"

failures=0
printf 'densty = 0.1\n' >typo.toml
refused "--config: typo.toml: unknown key 'densty' for simulate; allowed: dim, particles, density" \
  simulate --config typo.toml
printf 'seed = 0x1g\n' >hex.toml
refused "--config: hex.toml line 1: '0x1g' is no integer of base 16 within 64 bits" simulate --config hex.toml
printf '{"restitution": 0.8}\n' >json.toml
refused "--config: json.toml line 1: expected key = value \(a config file is TOML, key = value lines; JSON is not read\)" \
  simulate --config json.toml
printf 'particles = 1__000\n' >underscores.toml
refused "--config: underscores.toml line 1: '1__000': an underscore in a number stands between two digits" \
  simulate --config underscores.toml
printf 'restitution = 1.5\n' >range.toml
refused "--config: range.toml: key 'restitution': --restitution: value 1.5 is outside the allowed range \(0, 1\]" \
  simulate --config range.toml
# A flag on the command line wins, but the file's value for it is checked all the same.
refused "--config: range.toml: key 'restitution': --restitution: value 1.5 is outside the allowed range" \
  simulate --config range.toml --restitution 0.9
# A refused value that came from the file (here a result file's relaxation, read for another
# method) names the file: the user did not type it.
"$bin" simulate --particles 100 --t-end 1 --out plain.csv --quiet 2>/dev/null || fail "plain run"
refused "--relax: value 20 is not allowed with method = dsmc.*\(the value is from --config plain.csv\)" \
  simulate --config plain.csv --method dsmc
# A run's parameters that another command has no option for are named, not dropped in silence;
# the TC model's duration, which changes the gas, is refused.
"$bin" theory --config plain.csv 2>&1 >/dev/null |
  grep -q '^note: --config plain.csv: theory has no option for the run.s randomize = none, seed = 1, t_end = 1, .*; not used$' ||
  fail "theory --config of a run does not name the run's length it leaves out"
refused "--config: run.csv: the run uses the TC model \(tc = 1e-04\), and sweep has no option for it" \
  sweep --config run.csv
# The same for the TOML of --write-config, a run's file too (it was refused: "unknown key").
"$bin" simulate --particles 100 --t-end 1 --out plain2.csv --write-config plain.toml --quiet 2>/dev/null ||
  fail "plain run with --write-config"
"$bin" theory --config plain.toml 2>&1 >/dev/null |
  grep -q '^note: --config plain.toml: theory has no option for the run.s randomize = none, seed = 1, t_end = 1, .*; not used$' ||
  fail "theory --config of a run's TOML does not take its state point"
refused "--config: run.toml: the run uses the TC model \(tc = 1e-04\), and sweep has no option for it" \
  sweep --config run.toml
# A key spelled as its flag in a result header is a key (it was skipped as a title line).
sed 's/^# tc = .*/&\n# t-end = 5/' run.csv >hyphen.csv
refused "--config: hyphen.csv: key 't-end' sets --t-end again \(first as 't_end'\)" \
  simulate --config hyphen.csv
# An edited tc of -0 is no TC model; a negative one is out of range, not a TC model.
sed 's/^# tc = .*/# tc = -0/' run.csv >minus_zero.csv
"$bin" theory --config minus_zero.csv >/dev/null 2>&1 || fail "theory refused a run with tc = -0"
sed 's/^# tc = .*/# tc = -1/' run.csv >negative_tc.csv
refused "--config: negative_tc.csv: tc: value -1 is outside the allowed range \[0, inf\)" \
  theory --config negative_tc.csv
# A refused file prints no note before its error: the note would say the file was used.
"$bin" sweep --particles 300 --seeds 2 --restitution 1 --t-end-elastic 5 --cache cache \
  --out for_theory.csv --threads 1 >/dev/null 2>&1 || fail "sweep for theory"
# A table of another command names its writer (was: "unknown key 'seeds'", as if damaged).
refused "--config: for_theory.csv: a table of molchaos sweep, which theory does not read; .molchaos sweep --config for_theory.csv. repeats it" \
  theory --config for_theory.csv
printf 'contacts = yes\n' >flag.toml
refused "key 'contacts'.*true or false" simulate --config flag.toml
refused "key 'contacts'.*true or false" simulate --config flag.toml --contacts
# TOML strings: the escapes decoded as TOML defines them (a dropped backslash named another
# file), an escape TOML lacks refused, an escaped quote no end of the string, nested arrays refused.
cat >escapes.toml <<'TOML'
particles = 50
t_end = 1
out = "back\\slash \"q\" fl\u0075x.csv" # a comment after the string
TOML
"$bin" simulate --config escapes.toml --quiet 2>/dev/null || fail "run from escapes.toml"
[ -s 'back\slash "q" flux.csv' ] || fail "the TOML escapes of a string are not decoded: $(ls | grep -a slash)"
printf 'out = "sub\\qrun.csv"\n' >bad_escape.toml
refused "--config: bad_escape.toml line 1: unknown escape '\\\\q' in a string" \
  simulate --config bad_escape.toml
printf 'out = "C:\\runs\\new.csv"\n' >windows.toml  # \r and \n: control characters
refused "--config: windows.toml line 1: a control character in a string .*'single quotes'" \
  simulate --config windows.toml
printf 'out = {a = 1}\n' >inline.toml
refused "--config: inline.toml line 1: inline tables are not used" simulate --config inline.toml
printf 'snapshot-times = [0.001,, 0.005]\n' >hole.toml
refused "--config: hole.toml line 1: an empty element in an array" simulate --config hole.toml
printf 'density = [0.05, [0.1]]\n' >nested.toml
refused "--config: nested.toml line 1: arrays inside arrays are not used" sweep --config nested.toml
printf 'density = 0.1\nt_end = 5\ndensity = 0.2\n' >twice.toml
refused "--config: twice.toml: key 'density' sets --density again \(first as 'density'\); give each option once" \
  simulate --config twice.toml
printf 'density = [0.1, 0.2]\n' >array.toml
refused "--config: array.toml: key 'density': --density: takes one value, the file gives 2; give one" \
  simulate --config array.toml
printf 'dimension = 3\ndim = 2\n' >aliases.toml
refused "aliases.toml: key 'dim' sets --dim again \(first as 'dimension'\)" simulate --config aliases.toml
printf '[simulate]\ndensity = 0.1\n' >table.toml
refused "table.toml line 1: tables are not used" simulate --config table.toml
printf '# settings\n[simulate]\ndensity = 0.1\n' >commented_table.toml
refused "commented_table.toml line 2: tables are not used" simulate --config commented_table.toml
printf 'seeds = 0\n' >seeds.toml
refused "key 'seeds'.*--seeds.*\[1, 100000\]" sweep --config seeds.toml
printf 'b = 2\n' >b.toml
refused "--b: value 2 is outside the allowed range \[-2, 0.67121595[0-9]*\)" theory --config b.toml
refused "unknown key 'density' for reproduce" reproduce --config sweep.toml
refused "unknown key 'density' for bench; allowed: theory, simulation, particles, work, threads, out" \
  bench --config sweep.toml
printf 'simulation = true\nparticles = [50]\n' >bench_range.toml
refused "--config: bench_range.toml: key 'particles': --particles: value 50 is outside the allowed range \[100, 10000000\]" \
  bench --config bench_range.toml
refused "--config.*missing.toml" simulate --config missing.toml
refused "--config: /dev/zero: longer than 16 MiB" simulate --config /dev/zero  # read to its end once
# An empty list keeps an option's default: refused where that would drop the key unseen (a
# single value, a sweep's list), accepted for snapshot_times, whose default is the empty list.
printf 'density = []\n' >empty.toml
refused "--config: empty.toml: key 'density': --density: an empty value or list; give one value" \
  simulate --config empty.toml
refused "key 'density': --density: an empty value or list; give at least one value" \
  sweep --config empty.toml
printf 'snapshot_times = []\n' >no_snapshots.toml
"$bin" simulate --config no_snapshots.toml --particles 100 --t-end 1 --relax 1 --out none.csv \
  --quiet 2>/dev/null || fail "snapshot_times = [] refused"
# A run's header cut short repeats no run: the missing values would run as defaults. Cut inside a
# line ("# t_end = 3" of "30"), at a line end before the last parameters, inside an XYZ comment line.
head -c "$(($(grep -b '^# t_end = ' run.csv | cut -d: -f1) + 11))" run.csv >cut_value.csv
refused "--config: cut_value.csv: ends in the middle of its header line '# t_end = 3' \(a file cut short\?\)" \
  simulate --config cut_value.csv
sed '/^# tc = /,$d' run.csv >cut_lines.csv
refused "--config: cut_lines.csv: the run's header lacks tc, samples_per_decade, t_first_sample, contact_statistics, snapshot_times, max_collisions, min_temperature \(a file cut short\?\)" \
  simulate --config cut_lines.csv
if [ -f traj.xyz ]; then
  head -c "$(($(grep -b -o 't_end=' traj.xyz | head -n 1 | cut -d: -f1) + 7))" traj.xyz >cut.xyz
  refused "--config: cut.xyz: ends in the middle of its first comment line \(a file cut short\?\)" \
    simulate --config cut.xyz
fi
# No output may replace the file the options came from (a hand-written TOML replaced by a CSV):
# refused before any work, the file unchanged; nor may a sweep's summary land among its cached runs.
cp run.toml own.toml
refused "--config: 'own.toml' is also the file of --out, which would replace what this command reads" \
  simulate --config own.toml --out own.toml
refused "--config: './own.toml' is also the file of --write-config" \
  simulate --config ./own.toml --write-config own.toml --out other.csv
printf 'particles = 100\nseeds = 2\n' >sweep.toml
cp sweep.toml own_sweep.toml
refused "--config: 'own_sweep.toml' is also the file of --out" \
  sweep --config own_sweep.toml --out own_sweep.toml --cache ''
cmp sweep.toml own_sweep.toml || fail "the sweep's --config file was changed by a refused command"
cmp run.toml own.toml || fail "the --config file was changed by a refused command"
refused "--out: 'cache/../cache/s.csv' lies in the --cache folder 'cache', whose files are the cached runs" \
  sweep --seeds 1 --cache cache --out cache/../cache/s.csv
# A value echoed from a file shows its control bytes as \xNN: an escape sequence would drive the
# terminal, a NUL end the message.
printf '# molchaos run\n# version = x\n# randomize = pa\033[31mper\n# t_end = 1\nt,T\n' >escape.csv
refused "--config: escape.csv: key 'randomize': --randomize: unknown value 'pa\\\\x1b\\[31mper'" \
  simulate --config escape.csv
# A binary file is no text config (was: "line 1: expected key = value", as if a line were
# mistyped).
{ printf 'x'; head -c 200 /dev/urandom; printf '\0'; } >binary.cfg
refused "--config: binary.cfg: not a text file .*TOML file, a result CSV, an extended XYZ file, an H5MD trajectory" \
  simulate --config binary.cfg
# TOML types its values: a bare word is no value (was: read as the string), a quoted number is a
# string, refused for an option that takes a number (was: read as the number), and so is a quoted
# boolean for a flag (was: read as the boolean).
printf 'particles = 100\nrandomize = paper\n' >bare.toml
refused "--config: bare.toml line 2: key 'randomize': 'paper' is no TOML value: a string is written in quotes \\(randomize = \"paper\"\\)" \
  simulate --config bare.toml
printf 'density = [0.1, none]\n' >bare_list.toml
refused "--config: bare_list.toml line 1: key 'density': 'none' is no TOML value" sweep --config bare_list.toml
printf 'randomize = "paper"\nparticles = "100"\n' >quoted.toml
refused "--config: quoted.toml line 2: key 'particles': --particles takes a number, and the value is a string in quotes; write it bare \\(particles = 100\\)" \
  simulate --config quoted.toml
printf 'contacts = "true"\n' >quoted_flag.toml
refused "--config: quoted_flag.toml line 1: key 'contacts': --contacts takes true or false, and the value is a string in quotes; write it bare \\(contacts = true\\)" \
  simulate --config quoted_flag.toml
printf 'density = [0.1, "0.2"]\n' >quoted_list.toml
refused "--config: quoted_list.toml line 1: key 'density': --density takes a number" sweep --config quoted_list.toml
# A seed beyond 2^63 - 1, which a TOML integer cannot hold (was: written bare, which strict TOML
# readers refuse), is written in quotes and read back as the number; a smaller one stays bare.
"$bin" simulate --particles 50 --t-end 1 --relax 0 --seed 18446744073709551615 --out big_seed.csv \
  --write-config big_seed.toml --quiet 2>/dev/null || fail "run with the largest seed"
grep -qx 'seed = "18446744073709551615"' big_seed.toml || fail "a seed beyond TOML's integers bare"
"$bin" simulate --config big_seed.toml --out big_seed_again.csv --quiet 2>/dev/null ||
  fail "run from the TOML of the largest seed"
cmp big_seed.csv big_seed_again.csv || fail "the run of the largest seed repeated differs"
"$bin" simulate --particles 50 --t-end 1 --relax 0 --seed 9223372036854775807 --out top.csv \
  --write-config top.toml --quiet 2>/dev/null || fail "run with seed 2^63 - 1"
grep -qx 'seed = 9223372036854775807' top.toml || fail "seed 2^63 - 1 not bare"
# Beyond 2^64 - 1 in quotes: refused for its range (was: told to write it bare, which is refused).
printf 'seed = "18446744073709551616"\n' >beyond_seed.toml
refused "--config: beyond_seed.toml: key 'seed': --seed: value 18446744073709551616 is outside the allowed range \\[0, 18446744073709551615\\]" \
  simulate --config beyond_seed.toml
[ "$failures" -eq 0 ] || fail "$failures errors wrong"
echo "ok: unknown keys and out-of-range values named with their allowed range; cut headers refused"
