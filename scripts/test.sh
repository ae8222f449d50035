#!/usr/bin/env bash
# Quick start, step 2: build and run the tests: the unit tests (CTest) and the quick
# variants of the verification cases (report in verification-report/).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
bash scripts/build.sh
(cd build && ctest --output-on-failure -j2)
./build/cli/lituya verify -o verification-report --force
