# Sourced by compare_engines.sh and compare_reference.sh: the awk functions both use to read and
# summarise collision rates. Prepend "$rates_awk" to an awk program.
#   millions(v)  a rate as Google Benchmark prints it (suffix k or M) or as a plain number, in millions
#   sort(a, n)   sorts a[1..n] in place (insertion sort: a handful of rounds)
#   med(a, n)    the median of a sorted a[1..n]
# shellcheck disable=SC2034  # used by the sourcing scripts
rates_awk='
  function millions(v,   m) {
    m = 1
    if (v ~ /k$/) { m = 1e3; sub("k$", "", v) } else if (v ~ /M$/) { m = 1e6; sub("M$", "", v) }
    return v * m / 1e6
  }
  function sort(a, n,   i, j, t) {
    for (i = 2; i <= n; ++i) for (j = i; j > 1 && a[j-1] > a[j]; --j) { t = a[j]; a[j] = a[j-1]; a[j-1] = t }
  }
  function med(a, n) { return n % 2 ? a[(n+1)/2] : (a[n/2] + a[n/2+1]) / 2 }
'
