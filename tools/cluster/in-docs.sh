#!/bin/bash
# Fails unless every line of SCRIPT appears in DOC, so that a recipe in the docs is the tested
# script itself.
#   tools/cluster/in-docs.sh SCRIPT DOC
set -euo pipefail
missing=0
while IFS= read -r line; do
  [ -z "$line" ] && continue
  if ! grep -qxF -- "$line" "$2"; then
    echo "in-docs: $2 lacks this line of $1: $line"
    missing=1
  fi
done < "$1"
exit "$missing"
