#!/usr/bin/env bash
# `make run`: reproduce the paper's experiments with the built tools; results in out/.
set -euo pipefail
build=${1:-build}
mkdir -p out
echo "== cartan geometry tour (Lie groups, Cartan-Schouten connections, transport, reduction) =="
"$build/examples/geometry_tour" | tee out/geometry_tour.txt
echo
echo "== The paper's experiments: SO(3) free rigid body and oscillator, H3 oscillator =="
/usr/bin/python3 scripts/paper_experiments.py "$build" out | tee out/paper_experiments.txt
echo
echo "== The general theory: a particle on S^2, the free rigid body under five connections =="
/usr/bin/python3 scripts/general_figures.py "$build" out | tee out/general_figures.txt
