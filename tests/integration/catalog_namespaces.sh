#!/usr/bin/env bash
# Integration test of prism_add_shaders()'s namespaces (issue 22, item 4), configure only:
# a catalogue with no NAMESPACE takes its target's name as a C identifier (toon-shaders ->
# toon_shaders), so two catalogues never share <ns>::kCatalog; a second catalogue given a
# namespace another already has is a configure error naming both. And the source records
# for hot reload (<header>_sources.hpp) hold what each catalogue was given. A VARIANTS value
# that its axis lacks is a configure error at the caller's line naming the values (issue 37).
#
# Usage: catalog_namespaces.sh --source <prism source> --work <scratch dir> [--cmake <cmake>]
set -uo pipefail
SOURCE="" WORK="" CMAKE=cmake
while [ $# -gt 0 ]; do
  case "$1" in
    --source) SOURCE=$2; shift 2 ;;
    --work) WORK=$2; shift 2 ;;
    --cmake) CMAKE=$2; shift 2 ;;
    *) echo "catalog_namespaces.sh: unknown argument '$1'" >&2; exit 2 ;;
  esac
done
if [ -z "$SOURCE" ] || [ -z "$WORK" ]; then
  echo "usage: catalog_namespaces.sh --source <prism source> --work <scratch dir> [--cmake <cmake>]" >&2
  exit 2
fi
unset CMAKE_GENERATOR
rm -rf "$WORK" && mkdir -p "$WORK"
PROJECT=$SOURCE/tests/integration/catalog_namespaces
FAILURES=0
pass() { echo "PASS: $*"; }
fail() { echo "FAIL: $*"; FAILURES=$((FAILURES + 1)); }
show_log() { echo "  --- last lines of $1:"; tail -n 25 "$1" | sed 's/^/  | /'; }
# CMake wraps a message's lines: the checks read the log as one line.

if "$CMAKE" -S "$PROJECT" -B "$WORK/default" -DPRISM_SOURCE_DIR="$SOURCE" >"$WORK/default.log" 2>&1 &&
   grep -q -- "-- namespaces: toon_shaders lit_shaders$" "$WORK/default.log"; then
  pass "no NAMESPACE: each catalogue takes its target's name (toon-shaders -> toon_shaders, lit_shaders)"
else
  fail "no NAMESPACE: the target's name"; show_log "$WORK/default.log"
fi

if grep -q -- "-- source records: as given$" "$WORK/default.log"; then
  pass "the source records (<header>_sources.hpp) hold the folders, contract and defines given"
else
  fail "the source records"; show_log "$WORK/default.log"
fi

if "$CMAKE" -S "$PROJECT" -B "$WORK/same" -DPRISM_SOURCE_DIR="$SOURCE" -DSECOND_WITH_SAME_NAMESPACE=ON \
     >"$WORK/same.log" 2>&1; then
  fail "a second catalogue with namespace toon_shaders configured"; show_log "$WORK/same.log"
elif tr -s ' \n' ' ' <"$WORK/same.log" | grep -q "prism_add_shaders(more_toon): NAMESPACE toon_shaders is \
already the namespace of the catalogue toon-shaders"; then
  pass "a second catalogue with namespace toon_shaders is a configure error naming both"
else
  fail "the error for a second catalogue with namespace toon_shaders"; show_log "$WORK/same.log"
fi
# A VARIANTS value its axis does not have: a configure error at the caller's line, with the values.
line=$(grep -n "prism_add_shaders(bad_variant_shaders" "$PROJECT/CMakeLists.txt" | cut -d: -f1)
if "$CMAKE" -S "$PROJECT" -B "$WORK/bad-variant" -DPRISM_SOURCE_DIR="$SOURCE" -DBAD_VARIANT_VALUE=ON \
     >"$WORK/bad-variant.log" 2>&1; then
  fail "VARIANTS toon:LIGHTS=3 (the axis takes 1 2 4) configured"; show_log "$WORK/bad-variant.log"
elif tr -s ' \n' ' ' <"$WORK/bad-variant.log" | grep -q "prism_add_shaders(bad_variant_shaders): VARIANTS \
toon:FOG=1,LIGHTS=3: the variant axis LIGHTS takes 1, 2, 4, not 3" &&
     grep -q "CMakeLists.txt:$line (prism_add_shaders)" "$WORK/bad-variant.log"; then
  pass "a VARIANTS value the axis lacks is a configure error at CMakeLists.txt:$line listing the axis's values"
else
  fail "the error for VARIANTS toon:LIGHTS=3"; show_log "$WORK/bad-variant.log"
fi
echo "catalog_namespaces: $FAILURES failed check(s)"
[ "$FAILURES" -eq 0 ]
