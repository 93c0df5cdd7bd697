#!/usr/bin/env bash
# Installs the built motoflex into a scratch prefix, builds tests/consumer against that prefix
# alone and runs its Nao rollout on the installed bundled scenario.
#   tests/consumer/run_consumer_test.sh BUILD_DIR SOURCE_DIR
set -euo pipefail
build_dir=$1
source_dir=$2
scratch=$(mktemp -d "${TMPDIR:-/tmp}/motoflex_consumer.XXXXXX")
trap 'rm -rf "$scratch"' EXIT
cmake --install "$build_dir" --prefix "$scratch/prefix" > "$scratch/install.log"
cmake -S "$source_dir/tests/consumer" -B "$scratch/build" -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_PREFIX_PATH="$scratch/prefix" > "$scratch/configure.log" ||
  { cat "$scratch/configure.log"; exit 1; }
cmake --build "$scratch/build" -j 2 > "$scratch/build.log" || { tail -40 "$scratch/build.log"; exit 1; }
"$scratch/build/nao_rollout" "$scratch/prefix/share/motoflex/scenarios/nao_default.yaml"
