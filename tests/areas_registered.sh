#!/usr/bin/env bash
# test_areas_registered: the test areas this build should have are registered with ctest, and
# the areas the build left out are listed. Arguments: the ctest program, the build tree, then
# any number of
#   expect=LABEL=WHY       at least one test labelled LABEL must be registered (WHY: the reason)
#   left-out=WHAT          an area configured out or not found: printed, not failed
set -euo pipefail
ctest=$1
build=$2
shift 2
failures=0
for spec in "$@"; do
  case $spec in
    expect=*)
      rest=${spec#expect=}
      label=${rest%%=*}
      why=${rest#*=}
      count=$("$ctest" --test-dir "$build" -N -L "^${label}\$" | sed -n 's/^Total Tests: //p')
      if [[ -z $count || $count == 0 ]]; then
        echo "FAIL: no test labelled '$label' is registered, though $why"
        failures=$((failures + 1))
      else
        echo "ok   - $count tests labelled '$label' ($why)"
      fi ;;
    left-out=*)
      echo "LEFT OUT: ${spec#left-out=}" ;;
    *)
      echo "FAIL: unknown argument '$spec'"
      failures=$((failures + 1)) ;;
  esac
done
((failures == 0))
