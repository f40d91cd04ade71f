#!/usr/bin/env bash
# Writes unittest/costs.txt, the test costs a new build's ctest starts from
# (longest first), from the costs ctest measured in build directories:
#   tools/test-costs.sh build build-29Sep2021
# Each test keeps its largest cost; tests under 2 s are left to ctest.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
[ $# -gt 0 ] || set -- build
files=()
for dir in "$@"; do
  files+=("$dir/Testing/Temporary/CTestCostData.txt")
done
{
  awk '/^---/ { nextfile } NF == 3 && $3 >= 2 { if ($3 > cost[$1]) cost[$1] = $3 }
       END { for (t in cost) printf "%s 1 %.1f\n", t, cost[t] }' "${files[@]}" | sort -k3,3nr
  echo ---
} > "$root/unittest/costs.txt"
echo "$(grep -c ' 1 ' "$root/unittest/costs.txt") test costs in unittest/costs.txt"
