#!/bin/bash
# The layers of design.md section 1, bottom up: predicates/ (the kernels; the
# only place that decides signs) includes nothing of the project but
# predicates/; algorithms/ includes only predicates/ and algorithms/ (never
# variants/, which instantiates the algorithms). Usage: test_layering.sh SOURCE_DIR
set -u
src=${1:?usage: test_layering.sh SOURCE_DIR}
status=0
check() {  # check DIR ALLOWED-PREFIX-REGEX
  local dir=$1 allowed=$2 bad
  [ -d "$src/$dir" ] || { echo "missing directory $src/$dir"; status=1; return; }
  bad=$(grep -rnE '^[[:space:]]*#[[:space:]]*include[[:space:]]*"' "$src/$dir" --include='*.hpp' --include='*.cpp' |
        grep -vE "#[[:space:]]*include[[:space:]]*\"($allowed)/")
  if [ -n "$bad" ]; then
    echo "$dir/ includes outside its layer (allowed: $allowed):"
    echo "$bad"
    status=1
  fi
}
check predicates 'predicates'
check algorithms 'predicates|algorithms'
[ $status = 0 ] && echo "layering: predicates/ and algorithms/ include only their own layers and those below"
exit $status
