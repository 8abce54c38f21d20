#!/usr/bin/python3
"""Reference torques for the seed's validation vessel in 3D (docs/power.md, "The vessel in 3D:
a finite-element reference"): a flat plate turning about the axis of a closed cylindrical
vessel, by Taylor-Hood (P2-P1) finite elements on a tetrahedral mesh graded towards the plate.
The flow is solved in the frame turning with the plate, where it is steady: the plate at rest,
the vessel's walls turning at -omega. Stokes flow (Newtonian or the seed's CMC power law, the
latter by Newton's method after three Picard steps), or steady Navier-Stokes flow at
Re = rho N d^2 / mu (d the plate's length) with the Coriolis term (the centrifugal term is a
gradient and goes into the pressure). The torque follows from the dissipation,
T omega = int 2 mu eps(u):eps(u) dV: the Coriolis force does no work and exerts no torque about
the axis on a flow without normal flux through the walls, so the plate's torque equals the
walls' in either frame. Printed: the torque, Np Re = P / (mu N^2 d^3) for a Newtonian fluid,
and for the CMC the Newtonian viscosity of the same torque and the Metzner-Otto constant k it
implies (seed eq. 27). Check (`sphere`): a sphere of radius 0.075 m turning inside one of
0.15 m, whose torque is 8 pi mu omega R1^3 R2^3 / (R2^3 - R1^3). The power-law path has no
closed-form check in 3D; its k for the 8 mm plate (8.44) meets the 2D section's 8.46.

    tools/vessel_flow_reference.py plate THICKNESS HMIN [RE] [--top lid|slip] [--plate-top Z]
    tools/vessel_flow_reference.py plate THICKNESS HMIN --cmc [--rpm RPM] [--rho RHO] [...]
    tools/vessel_flow_reference.py sphere HMIN

THICKNESS and HMIN (the element size at the plate's edges) in metres. The vessel and plate are
the test's (tests/validation/stirred_vessel_test.cpp): radius 0.15 m, lid at 0.3 m, plate
0.15 m long from z = 0.014 to 0.294 m; `--top slip` makes the top a free-slip plane (a flat
free surface) and `--plate-top` moves the plate's top edge. The speed defaults to 1 rad/s (Np Re
and k do not depend on it in Newtonian Stokes flow; the CMC's k does, through the viscosity
bounds, so docs/ use `--rpm 60`). With inertia (RE > 0) each Newton step is a direct solve
(MUMPS): GMRES with the Stokes block preconditioner, which leaves out convection and the Coriolis
term, had not converged in 20 minutes at Re = 10. The direct solve is the cost: at Re = 10 on
the 12 mm mesh (161,000 unknowns) four Newton steps took 52 minutes and 6 GB on one core; the
Newtonian run also prints the Stokes flow's Np Re on the same mesh. Needs FEniCS 2019
(python3-dolfin) and gmsh (python3-gmsh, python3-meshio): scripts/install-reference-tools.sh.
"""
import argparse
import math
import os
import sys
import tempfile

import dolfin as df
import gmsh
import meshio
import numpy as np
import ufl

R, H = 0.15, 0.3  # vessel radius and the lid's height (m)
A = 0.075  # the plate's half-length
Z0 = 0.014  # the plate's clearance above the floor
MU = 1.0  # the Newtonian viscosity (Pa s); Np Re does not depend on it
D = 2.0 * A

# Quadrature of degree 4: exact for the Newtonian terms of P2-P1, and enough for the power
# law's viscosity, which would otherwise ask for hundreds of points a cell.
DX = df.dx(metadata={"quadrature_degree": 4})


def plate_mesh(thickness, z1, hmin, path):
    """The fluid between the vessel and the plate, tetrahedra graded from hmin at the plate's
    edges to 16 hmin (at most 15 mm) far from it."""
    gmsh.initialize()
    gmsh.option.setNumber("General.Terminal", 0)
    occ = gmsh.model.occ
    vessel = occ.addCylinder(0, 0, 0, 0, 0, H, R)
    plate = occ.addBox(-A, -thickness / 2, Z0, 2 * A, thickness, z1 - Z0)
    occ.cut([(3, vessel)], [(3, plate)])
    occ.synchronize()
    eps = 1e-6
    plate_curves = [
        c for (_, c) in gmsh.model.getEntitiesInBoundingBox(
            -A - eps, -thickness / 2 - eps, Z0 - eps, A + eps, thickness / 2 + eps, z1 + eps, 1)
    ]
    plate_faces = [
        s for (_, s) in gmsh.model.getEntitiesInBoundingBox(
            -A - eps, -thickness / 2 - eps, Z0 - eps, A + eps, thickness / 2 + eps, z1 + eps, 2)
    ]
    field = gmsh.model.mesh.field
    edges = field.add("Distance")
    field.setNumbers(edges, "CurvesList", plate_curves)
    field.setNumber(edges, "NumPointsPerCurve", 200)
    faces = field.add("Distance")
    field.setNumbers(faces, "SurfacesList", plate_faces)
    field.setNumber(faces, "NumPointsPerCurve", 60)
    hmax = min(16 * hmin, 0.015)
    near_edges = field.add("Threshold")
    field.setNumber(near_edges, "InField", edges)
    field.setNumber(near_edges, "SizeMin", hmin)
    field.setNumber(near_edges, "SizeMax", hmax)
    field.setNumber(near_edges, "DistMin", 0.0)
    field.setNumber(near_edges, "DistMax", 0.08)
    near_faces = field.add("Threshold")
    field.setNumber(near_faces, "InField", faces)
    field.setNumber(near_faces, "SizeMin", 2 * hmin)
    field.setNumber(near_faces, "SizeMax", hmax)
    field.setNumber(near_faces, "DistMin", 0.0)
    field.setNumber(near_faces, "DistMax", 0.06)
    smallest = field.add("Min")
    field.setNumbers(smallest, "FieldsList", [near_edges, near_faces])
    field.setAsBackgroundMesh(smallest)
    gmsh.option.setNumber("Mesh.MeshSizeExtendFromBoundary", 0)
    gmsh.option.setNumber("Mesh.MeshSizeFromPoints", 0)
    gmsh.option.setNumber("Mesh.MeshSizeFromCurvature", 12)
    gmsh.model.mesh.generate(3)
    gmsh.write(path + ".msh")
    gmsh.finalize()
    return to_dolfin(path)


def sphere_mesh(hmin, path):
    """The fluid between spheres of radius R/2 and R, uniform tetrahedra of size hmin."""
    gmsh.initialize()
    gmsh.option.setNumber("General.Terminal", 0)
    occ = gmsh.model.occ
    outer = occ.addSphere(0, 0, 0, R)
    inner = occ.addSphere(0, 0, 0, R / 2)
    occ.cut([(3, outer)], [(3, inner)])
    occ.synchronize()
    gmsh.option.setNumber("Mesh.MeshSizeMin", hmin)
    gmsh.option.setNumber("Mesh.MeshSizeMax", hmin)
    gmsh.model.mesh.generate(3)
    gmsh.write(path + ".msh")
    gmsh.finalize()
    return to_dolfin(path)


def to_dolfin(path):
    msh = meshio.read(path + ".msh")
    tets = msh.get_cells_type("tetra")
    meshio.write(path + ".xdmf", meshio.Mesh(points=msh.points, cells={"tetra": tets}))
    mesh = df.Mesh()
    with df.XDMFFile(path + ".xdmf") as f:
        f.read(mesh)
    return mesh


def krylov(tol):
    """MINRES with BoomerAMG on the block preconditioner (the symmetric systems: Stokes flow
    and the power law's Newton steps)."""
    solver = df.PETScKrylovSolver("minres", "hypre_amg")
    solver.parameters["relative_tolerance"] = tol
    solver.parameters["maximum_iterations"] = 5000
    return solver


class Fluid:
    """Newtonian (viscosity MU) or the seed's CMC power law (K 13.9 Pa s^n, n 0.47, viscosity
    between 0.1 and 40 Pa s as cases/youcefi_vessel_cmc.yaml), at the density rho (0: Stokes)
    and the plate's speed omega [rad/s]."""

    K, FLOW_INDEX, LOWEST, HIGHEST = 13.9, 0.47, 0.1, 40.0

    def __init__(self, power_law, rho, omega):
        self.power_law, self.rho, self.omega = power_law, rho, omega
        # The Stokes start: the power law's viscosity at a Metzner-Otto constant of 8.
        self.start = self.K * (8.0 * omega / (2 * math.pi))**(self.FLOW_INDEX - 1) if power_law else MU

    def viscosity(self, u):
        if not self.power_law:
            return df.Constant(MU)
        rate = df.sqrt(2 * df.inner(df.sym(df.grad(u)), df.sym(df.grad(u))) + 1e-12)
        return ufl.min_value(ufl.max_value(self.K * rate**(self.FLOW_INDEX - 1), self.LOWEST),
                             self.HIGHEST)


def solve(mesh, on_body, top_slip, fluid):
    """The flow with the body at rest and the outer walls turning at -omega about z: the
    dissipation of the Stokes flow at the starting viscosity, the dissipation of the flow, and
    the number of unknowns. The preconditioner is the velocity's vector Laplacian beside the
    pressure's mass matrix, both weighted by the viscosity (the FEniCS Stokes demo's choice),
    spectrally equivalent to the Stokes operator."""
    p2 = df.VectorElement("P", mesh.ufl_cell(), 2)
    p1 = df.FiniteElement("P", mesh.ufl_cell(), 1)
    space = df.FunctionSpace(mesh, df.MixedElement([p2, p1]))
    wall_velocity = df.Expression(("w*x[1]", "-w*x[0]", "0.0"), w=fluid.omega, degree=1)
    top = lambda x, b: b and not on_body(x) and x[2] > H - 1e-7
    outer = lambda x, b: b and not on_body(x) and not (top_slip and x[2] > H - 1e-7)
    bcs = [
        df.DirichletBC(space.sub(0), df.Constant((0.0, 0.0, 0.0)), lambda x, b: b and on_body(x)),
        df.DirichletBC(space.sub(0), wall_velocity, outer),
    ]
    if top_slip:
        bcs.append(df.DirichletBC(space.sub(0).sub(2), df.Constant(0.0), top))
    u, p = df.TrialFunctions(space)
    v, q = df.TestFunctions(space)
    mu = df.Constant(fluid.start)
    zero = df.inner(df.Constant((0.0, 0.0, 0.0)), v) * DX
    a, b = df.assemble_system(stokes_form(u, p, v, q, mu), zero, bcs)
    pre, _ = df.assemble_system(block_form(u, p, v, q, mu), zero, bcs)
    solver = krylov(1e-10)
    solver.set_operators(a, pre)
    w = df.Function(space)
    iterations = solver.solve(w.vector(), b)
    print(f"  Stokes: {iterations} MINRES iterations", flush=True)
    stokes = dissipation(w, mu)
    if fluid.rho > 0 or fluid.power_law:
        newton(space, w, bcs, fluid)
    return stokes, dissipation(w, fluid.viscosity(df.split(w)[0])), space.dim()


def stokes_form(u, p, v, q, mu):
    eps = lambda f: df.sym(df.grad(f))
    return (2 * mu * df.inner(eps(u), eps(v)) - p * df.div(v) - q * df.div(u)) * DX


def block_form(u, p, v, q, mu):
    return (mu * df.inner(df.grad(u), df.grad(v)) + p * q / mu) * DX


def dissipation(w, mu):
    u = df.split(w)[0]
    return df.assemble(2 * mu * df.inner(df.sym(df.grad(u)), df.sym(df.grad(u))) * DX)


def newton(space, w, bcs, fluid):
    """Steady flow in the plate's frame (inertia with the Coriolis term, the power law's
    viscosity) by Newton's method from the Stokes flow w; for the power law the first three
    steps are Picard steps (the viscosity taken from the last iterate)."""
    spin = df.Constant((0.0, 0.0, fluid.omega))
    u, p = df.split(w)
    v, q = df.TestFunctions(space)
    trial_u, trial_p = df.TrialFunctions(space)
    mu = fluid.viscosity(u)
    residual = stokes_form(u, p, v, q, mu)
    picard = stokes_form(trial_u, trial_p, v, q, mu)
    if fluid.rho > 0:
        inertia = fluid.rho * df.inner(df.grad(u) * u + 2 * df.cross(spin, u), v) * DX
        residual += inertia
        picard += df.derivative(inertia, w)
    jacobian = df.derivative(residual, w)
    homogeneous = [df.DirichletBC(bc) for bc in bcs]
    for bc in homogeneous:
        bc.homogenize()
    step = df.Function(space)
    for k in range(40):
        form = picard if fluid.power_law and k < 3 else jacobian
        a, b = df.assemble_system(form, -residual, homogeneous)
        if fluid.rho > 0:
            # With inertia the Jacobian is not symmetric and the block preconditioner, which
            # leaves out convection and the Coriolis term, let GMRES stall: a direct solve.
            solver = df.PETScLUSolver("mumps")
            solver.set_operator(a)
            solver.solve(step.vector(), b)
            how = "direct solve"
        else:
            # Inexact Newton: the residual is exact, so a loose inner tolerance changes the
            # number of steps, not the answer. Without inertia the Jacobian is symmetric (the
            # power law's dissipation is a convex potential), and MINRES serves.
            pre, _ = df.assemble_system(block_form(trial_u, trial_p, v, q, mu), -residual,
                                        homogeneous)
            solver = krylov(1e-5)
            solver.set_operators(a, pre)
            how = f"{solver.solve(step.vector(), b)} MINRES iterations"
        w.vector().axpy(1.0, step.vector())
        size = step.split(deepcopy=True)[0].vector().norm("linf")
        print(f"  Newton {k}: {how}, velocity step {size:.3e}", flush=True)
        if size < 1e-8 * fluid.omega * R:
            return
    raise RuntimeError("Newton's method did not converge")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("body", choices=["plate", "sphere"])
    parser.add_argument("numbers", type=float, nargs="+")
    parser.add_argument("--top", choices=["lid", "slip"], default="lid")
    parser.add_argument("--plate-top", type=float, default=0.294)
    parser.add_argument("--cmc", action="store_true")
    parser.add_argument("--rho", type=float, default=0.0)
    parser.add_argument("--rpm", type=float, default=60.0 / (2 * math.pi))
    args = parser.parse_args()
    df.set_log_level(df.LogLevel.WARNING)
    path = os.path.join(tempfile.mkdtemp(), "mesh")
    omega = args.rpm * 2 * math.pi / 60
    if args.body == "sphere":
        mesh = sphere_mesh(args.numbers[0], path)
        _, power, dofs = solve(mesh, lambda x: np.linalg.norm(x) < 0.75 * R, False,
                               Fluid(False, 0.0, omega))
        exact = 8 * math.pi * MU * omega * (R / 2)**3 * R**3 / (R**3 - (R / 2)**3)
        print(f"sphere hmin {args.numbers[0]} cells {mesh.num_cells()} unknowns {dofs} "
              f"torque {power / omega:.6e} exact {exact:.6e} error {power / omega / exact - 1:+.4%}")
        return
    thickness, hmin = args.numbers[0], args.numbers[1]
    re = args.numbers[2] if len(args.numbers) > 2 else 0.0
    n = omega / (2 * math.pi)
    rho = args.rho if args.cmc else re * MU / (n * D * D)
    fluid = Fluid(args.cmc, rho, omega)
    z1 = args.plate_top
    mesh = plate_mesh(thickness, z1, hmin, path)
    tol = 1e-7
    on_plate = lambda x: (abs(x[0]) < A + tol and abs(x[1]) < thickness / 2 + tol and
                          Z0 - tol < x[2] < z1 + tol)
    stokes, power, dofs = solve(mesh, on_plate, args.top == "slip", fluid)
    head = (f"plate thickness {thickness} top {args.top} plate_top {z1} hmin {hmin} "
            f"cells {mesh.num_cells()} unknowns {dofs} torque {power / omega:.6e}")
    if not args.cmc:
        scale = MU * n * n * D**3
        print(f"{head} Re {re} NpRe {power / scale:.3f} NpRe_stokes {stokes / scale:.3f}")
        return
    # The Newtonian viscosity of the same torque, and the Metzner-Otto constant it implies:
    # K (k N)^(n-1) = mu_eff (seed eq. 27).
    mu_eff = power / (stokes / fluid.start)
    k = (mu_eff / Fluid.K)**(1 / (Fluid.FLOW_INDEX - 1)) / n
    print(f"{head} CMC rpm {args.rpm} rho {rho} mu_eff {mu_eff:.5f} metzner_otto_k {k:.4f} "
          f"Re_MO(k=7.54) {rho * n**(2 - Fluid.FLOW_INDEX) * D * D / (Fluid.K * 7.54**(Fluid.FLOW_INDEX - 1)):.4f}")


if __name__ == "__main__":
    sys.exit(main())
