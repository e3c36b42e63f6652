#!/usr/bin/env bash
# Sets up (tools/setup.sh) and runs the whole test suite with ctest. Safe to run again.
# assimp-testmodels: the model files assimp's own tests use, read by ModelFormats.AssimpTestModels;
# parallel: GNU parallel, which runs the recipe of docs/cluster.md in Cluster.GnuParallel*;
# python3-jsonschema: the validator of the bench's results file against its schema (BenchResults.*);
# python3-yaml: reads the CI recipes of docs/ci.md (Recipes.CiWorkflowsRunInOrder); chromium and
# python3-websocket: open the HTML bench report in a browser (BenchReport.OpensInChromium).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
# One apt-get run for these and setup's own packages.
"$root/tools/setup.sh" assimp-testmodels parallel python3-jsonschema python3-yaml chromium \
  python3-websocket
cd "$root/build"
ctest --output-on-failure -j 2
