#!/usr/bin/env bash
# The wide queries are the portable templates instantiated with AVX2 or AVX-512 lanes and flattened into the
# functions compiled for those instruction sets (core/src/entry.h: RunWide, RunWide512,
# WithSweepTracer). They are correct only when every call below those functions is inlined: a template with wide
# lanes left out of line is compiled for the baseline instruction set, and a call between it and the AVX code passes
# vector registers in a convention one side does not share. This check fails when the library holds any such
# function: a symbol that names the wide tracers or the wide lanes.
# Usage: wide_inlined.sh NM LIBRARY
set -euo pipefail
nm=$1
library=$2
symbols=$("$nm" -C "$library")
if ! grep -q "RunWide<" <<< "$symbols"; then
  echo "wide_inlined: $library has no RunWide: not the library of the wide queries, or built without them" >&2
  exit 1
fi
leaks=$(grep -E "WideNull|Wide512Null|Lanes<(double|float), true>|Lanes8" <<< "$symbols" || true)
if [ -n "$leaks" ]; then
  echo "wide_inlined: functions of the wide queries left out of line in $library:" >&2
  cut -c1-300 <<< "$leaks" | head -20 >&2
  exit 1
fi
echo "wide_inlined: every function of the wide queries is inlined ($(grep -c "RunWide" <<< "$symbols") wide entry points)"
