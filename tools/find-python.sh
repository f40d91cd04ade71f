#!/bin/sh
# Print the first python3 that imports numpy, scipy and matplotlib (Debian's
# /usr/bin/python3 has them; a python3 earlier on PATH may not).
for py in "${SPHTHERMAL_PYTHON:-}" python3 /usr/bin/python3; do
  [ -n "$py" ] || continue
  if "$py" -c "import numpy, scipy, matplotlib" >/dev/null 2>&1; then
    command -v "$py"
    exit 0
  fi
done
echo "find-python: no python3 with numpy, scipy and matplotlib (apt-get install python3-numpy python3-scipy python3-matplotlib)" >&2
exit 1
