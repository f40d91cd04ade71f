#!/bin/sh
# forced.examples.channel_continuity: in.channel's `continuity auto` holds
# the fluid's mean density under shifting below Re = 100 and lets it drift
# above (README.md of examples/forced-channel, "The drift of the mean
# density"), and an explicit value wins. Each case runs the input for no
# steps and reads the shift's keyword from the log.
#   continuity_auto.sh LMP PLUGIN WORKDIR
set -e
lmp=$1 plugin=$2 work=$3
root=$(cd "$(dirname "$0")/../.." && pwd)
mkdir -p "$work"
cd "$work"
status=0
check() { # re, continuity given, keyword expected
  "$lmp" -in "$root/examples/forced-channel/in.channel" -var plugin "$plugin" -var n 10 \
    -var length 20 -var re "$1" -var continuity "$2" -var tend 0 -var every 1 -var out c \
    -log log.c > /dev/null
  got=$(sed -n 's/^fix shift fluid sph\/shift .* continuity \(yes\|no\)$/\1/p' log.c | tail -n 1)
  if [ "$got" = "$3" ]; then
    echo "ok   Re = $1, continuity $2: $got"
  else
    echo "FAIL Re = $1, continuity $2: '$got', expected $3"
    status=1
  fi
}
check 65.2 auto yes
check 99 auto yes
check 100 auto no
check 652 auto no
check 65.2 no no
check 652 yes yes
exit $status
