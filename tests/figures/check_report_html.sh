#!/bin/sh
# REPORT.html in a real headless browser: `molchaos reproduce --quick` writes it, Chromium loads
# it, and a script run after the load event counts the images that decoded (naturalWidth > 0),
# the sources that are not embedded, and the in-page links whose target is missing. Chromium is
# a package of the Makefile's PACKAGES: its absence is a failure, not a skip.
# Usage: check_report_html.sh <molchaos binary> <work dir>
set -eu
molchaos=$1
work=$2
browser=$(command -v chromium || true)
if [ -z "$browser" ]; then
  echo "FAIL: chromium not found (install the Debian package chromium, listed in PACKAGES)" >&2
  exit 1
fi
rm -rf "$work"
mkdir -p "$work"
"$molchaos" reproduce --quick --threads 2 --out "$work/results" > "$work/reproduce.log" 2>&1 ||
  { cat "$work/reproduce.log"; exit 1; }
html=$work/results/REPORT.html
test -s "$html"
# The page must not depend on the folder: move it away from the figures before loading it.
mkdir -p "$work/alone"
sed 's#</body>#<script>window.addEventListener("load", () => {\
  const images = [...document.images];\
  const decoded = images.filter(i => i.complete \&\& i.naturalWidth > 0).length;\
  const external = images.filter(i => !i.src.startsWith("data:image/png;base64,")).length;\
  const links = [...document.querySelectorAll("a[href]")];\
  const broken = links.filter(a => !a.getAttribute("href").startsWith("\#") ||\
                                   !document.getElementById(a.getAttribute("href").slice(1)));\
  const out = document.createElement("pre");\
  out.id = "check";\
  out.textContent = `CHECK images=${images.length} decoded=${decoded} external=${external} links=${links.length} broken=${broken.length} h1=${document.querySelectorAll("h1").length} tables=${document.querySelectorAll("table").length}`;\
  document.body.appendChild(out);\
});</script></body>#' "$html" > "$work/alone/REPORT.html"
timeout 120 "$browser" --headless --no-sandbox --disable-gpu --disable-dev-shm-usage \
  --virtual-time-budget=10000 --dump-dom "file://$work/alone/REPORT.html" \
  > "$work/dom.html" 2> "$work/chromium.log" || { cat "$work/chromium.log"; exit 1; }
line=$(grep -o 'CHECK images=[0-9][^<]*' "$work/dom.html" || true)
echo "$line"
[ -n "$line" ] || { echo "FAIL: the check script did not run" >&2; exit 1; }
value() { echo "$line" | sed -n "s/.* $1=\([0-9]*\).*/\1/p"; }
figures=$(ls "$work/results"/*.png | wc -l)
fail=0
[ "$(value images)" -eq "$figures" ] || { echo "FAIL: $(value images) images, $figures PNG files" >&2; fail=1; }
[ "$(value decoded)" -eq "$figures" ] || { echo "FAIL: only $(value decoded) images decoded" >&2; fail=1; }
[ "$(value external)" -eq 0 ] || { echo "FAIL: images not embedded" >&2; fail=1; }
[ "$(value links)" -gt 0 ] || { echo "FAIL: no table of contents" >&2; fail=1; }
[ "$(value broken)" -eq 0 ] || { echo "FAIL: $(value broken) broken links" >&2; fail=1; }
[ "$(value h1)" -eq 1 ] && [ "$(value tables)" -ge 5 ] || { echo "FAIL: page structure" >&2; fail=1; }
exit $fail
