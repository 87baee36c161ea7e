#!/usr/bin/env bash
# `make docs`: the documentation site (docs/site) into OUT_DIR/html (default build/docs/html).
#   bash scripts/build-docs.sh [BUILD_DIR [OUT_DIR]]    (defaults build, BUILD_DIR/docs)
# Needs a build tree with the Python module and the examples (`make build`; BUILD_DIR/python, or
# CARTAN_PYTHON_PATH) and the packages of `scripts/install-deps.sh docs`. It first makes the
# gallery's inputs in OUT_DIR/gallery with the scripts of `make run` (a few seconds; the
# site shows figures of the code it documents, not whatever out/ holds), then runs Sphinx with
# warnings as errors (-W --keep-going: a broken reference, a missing figure or header fails).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=$(realpath -m "${1:-$root/build}")
python_path=$(realpath -m "${CARTAN_PYTHON_PATH:-$build/python}")
docs=$(realpath -m "${2:-$build/docs}")
cd "$root"
gallery=$docs/gallery
mkdir -p "$gallery"

py=/usr/bin/python3
$py scripts/paper_experiments.py "$(dirname "$python_path")" "$gallery" > "$gallery/paper_experiments.txt"
$py scripts/general_figures.py "$(dirname "$python_path")" "$gallery" > "$gallery/general_figures.txt"
for example in python_tour custom_lagrangian general_connections; do
  PYTHONPATH="$python_path" $py "examples/$example.py" > "$gallery/$example.py.txt"
done
for example in geometry_tour custom_group custom_lagrangian; do
  "$build/examples/$example" > "$gallery/$example.txt"
done

CARTAN_PYTHON_PATH="$python_path" CARTAN_DOCS_BUILD="$docs" \
  $py -m sphinx -b html -W --keep-going -q -d "$docs/doctrees" docs/site "$docs/html"
echo "build-docs: $docs/html/index.html"
