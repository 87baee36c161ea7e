#!/usr/bin/env bash
# `make run`: reproduce the paper's experiments with the built tools. Grows with the project.
set -euo pipefail
build=${1:-build}
mkdir -p out
echo "== cartan geometry tour (Lie groups, Cartan-Schouten connections, transport, reduction) =="
"$build/examples/geometry_tour" | tee out/geometry_tour.txt
