#!/bin/sh
# The packages of tools/vessel_flow_reference.py, the 3D finite-element reference for the
# validation vessel (docs/power.md): FEniCS 2019 (python3-dolfin, with PETSc, hypre and MUMPS),
# gmsh and meshio. Not needed to build, test or run partimix; make test does not install them.
set -eu
missing=""
for package in python3-dolfin python3-gmsh python3-meshio; do
  dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed" ||
    missing="$missing $package"
done
[ -z "$missing" ] && exit 0
apt-get update
# shellcheck disable=SC2086
apt-get install -y $missing
