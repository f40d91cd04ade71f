#!/usr/bin/env bash
# The docs, examples, benchmarks and sources cite the papers by author and
# year (doc/src/Bibliography_sphthermal.rst), never by an internal seed
# number or design file. Fails listing every line that does.
#   check_citations.sh
set -eu
root=$(cd "$(dirname "$0")/../.." && pwd)
cd "$root"
pattern='seed 0[0-9][0-9]|seeds? [0-9]{3}|seeds? 0[0-9]|SPEC\.md'
paths=(README.md doc examples bench src tools cmake unittest)

rc=0
hits=$(grep -rnIiE --exclude=check_citations.sh "$pattern" "${paths[@]}") || rc=$?
if [ "$rc" -eq 0 ]; then
  echo "$hits"
  echo "FAIL: the lines above cite a seed number or SPEC.md; cite the paper" \
       "(doc/src/Bibliography_sphthermal.rst)"
  exit 1
elif [ "$rc" -ne 1 ]; then
  echo "FAIL: grep could not read ${paths[*]} under $root"
  exit 1
fi
n=$(grep -rlIiE '' "${paths[@]}" | wc -l)
echo "ok: no file cites a seed number or SPEC.md; $n files checked"
