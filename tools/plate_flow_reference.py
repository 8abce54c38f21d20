#!/usr/bin/python3
"""Reference torques for tests/validation/rotating_plate_test.cpp (docs/power.md, "The rotating
plate in 2D"): the flow between a rectangle of half-length a and half-width b turning at omega
about its centre and a circle of radius R at rest, by Taylor-Hood (P2-P1) finite elements on a
mesh of rays from the centre, graded towards the rectangle's corners and towards both walls.
Stokes flow, or steady Navier-Stokes flow at a given Re = rho N d^2 / mu in the frame turning
with the rectangle (where it is steady), by Newton's method from the Stokes solution; or the
seed's CMC power law (Picard iteration on the viscosity), in Stokes flow or at a density. The torque
per unit depth follows from the dissipation, T omega = int 2 mu eps(u):eps(u) dA, which is the
power the body gives the fluid. Check: with the rectangle replaced by a circle of radius R1 the
script reproduces the Couette torque 4 pi mu omega R1^2 R^2 / (R^2 - R1^2), which inertia does
not change (run with `circle`).

    tools/plate_flow_reference.py plate N [RE]   # N rays per quarter turn (20, 40, 80)
    tools/plate_flow_reference.py circle N [RE]
    tools/plate_flow_reference.py plate N cmc [RHO]   # power law; circle: its Couette torque

Needs numpy and scipy (python3-numpy, python3-scipy); N = 40 takes about 30 s a solve, and the
power law 50-70 solves.
"""
import sys

import numpy as np
import scipy.sparse as sp
import scipy.sparse.linalg as spla

MU, RHO, OMEGA, R = 56.7, 1260.0, 2.0 * np.pi, 0.15  # the test's fluid, speed and vessel (SI)
A, B = 0.075, 0.015  # the plate: 0.15 m long, 0.03 m thick
R1 = 0.075  # the circle of the check


def graded(lo, hi, m):
    """m points from lo (included) to hi (excluded), clustered towards both ends."""
    s = 0.5 - 0.5 * np.cos(np.pi * np.linspace(0.0, 1.0, m + 1))
    return lo + (hi - lo) * s[:-1]


def plate_rays(n):
    """Ray angles, n per quarter turn, with a ray through each corner of the rectangle."""
    tc = np.arctan2(B, A)
    m1 = max(4, int(n * tc / (np.pi / 2)))
    m2 = n - m1
    return np.concatenate([graded(-tc, tc, 2 * m1), graded(tc, np.pi - tc, 2 * m2),
                           graded(np.pi - tc, np.pi + tc, 2 * m1),
                           graded(np.pi + tc, 2 * np.pi - tc, 2 * m2)])


def plate_radius(theta):
    """Distance from the centre to the rectangle along the ray at theta."""
    c, s = np.abs(np.cos(theta)), np.abs(np.sin(theta))
    with np.errstate(divide="ignore"):
        return np.minimum(np.where(c > 0, A / c, np.inf), np.where(s > 0, B / s, np.inf))


def ray_mesh(theta, inner_radius, n_radial):
    """Vertices on the rays from the body (inner_radius) to the circle R, and triangles."""
    t = 0.5 - 0.5 * np.cos(np.pi * np.linspace(0.0, 1.0, n_radial + 1))
    r = inner_radius[:, None] + t[None, :] * (R - inner_radius[:, None])
    points = np.stack([r * np.cos(theta)[:, None], r * np.sin(theta)[:, None]], -1).reshape(-1, 2)
    rays = len(theta)
    i, j = np.meshgrid(np.arange(rays), np.arange(n_radial), indexing="ij")
    a = i * (n_radial + 1) + j
    b = ((i + 1) % rays) * (n_radial + 1) + j
    quads = np.stack([a, b, b + 1, a + 1], -1).reshape(-1, 4)
    triangles = np.concatenate([quads[:, [0, 1, 2]], quads[:, [0, 2, 3]]])
    inner = np.arange(rays) * (n_radial + 1)
    return points, triangles, inner, inner + n_radial


def p2_shape(xi, eta):
    """P2 shape functions and their reference gradients at (xi, eta)."""
    l = np.array([1.0 - xi - eta, xi, eta])
    dl = np.array([[-1.0, -1.0], [1.0, 0.0], [0.0, 1.0]])
    phi = np.array([l[0] * (2 * l[0] - 1), l[1] * (2 * l[1] - 1), l[2] * (2 * l[2] - 1),
                    4 * l[0] * l[1], 4 * l[1] * l[2], 4 * l[2] * l[0]])
    dphi = np.array([(4 * l[0] - 1) * dl[0], (4 * l[1] - 1) * dl[1], (4 * l[2] - 1) * dl[2],
                     4 * (l[0] * dl[1] + l[1] * dl[0]), 4 * (l[1] * dl[2] + l[2] * dl[1]),
                     4 * (l[2] * dl[0] + l[0] * dl[2])])
    return l, phi, dphi


def quadrature_degree5():
    """Seven-point rule on the reference triangle, exact for degree 5 (Dunavant 1985)."""
    a, b = (6.0 - np.sqrt(15.0)) / 21.0, (6.0 + np.sqrt(15.0)) / 21.0
    wa, wb = (155.0 + np.sqrt(15.0)) / 2400.0, (155.0 - np.sqrt(15.0)) / 2400.0
    points = [(1 / 3, 1 / 3), (a, a), (1 - 2 * a, a), (a, 1 - 2 * a), (b, b), (1 - 2 * b, b),
              (b, 1 - 2 * b)]
    return points, [9.0 / 80.0, wa, wa, wa, wb, wb, wb]  # weights sum to 1/2, the area


class Mesh:
    """P2 velocity nodes and P1 pressure vertices of a triangle mesh, with reference geometry."""

    def __init__(self, points, triangles):
        self.nv = len(points)
        edges_all = np.sort(np.concatenate([triangles[:, [0, 1]], triangles[:, [1, 2]],
                                            triangles[:, [2, 0]]]), 1)
        self.edges, which = np.unique(edges_all, axis=0, return_inverse=True)
        mids = self.nv + which.reshape(3, -1).T
        self.nodes = np.vstack([points, 0.5 * (points[self.edges[:, 0]]
                                               + points[self.edges[:, 1]])])
        self.triangles, self.p2 = triangles, np.hstack([triangles, mids])
        x0, x1, x2 = (points[triangles[:, k]] for k in range(3))
        jac = np.stack([x1 - x0, x2 - x0], -1)
        self.area = 0.5 * np.abs(np.linalg.det(jac))
        self.jinv = np.linalg.inv(jac)

    def boundary(self, vertices):
        """Velocity nodes on the boundary through these vertices (vertices and edge midpoints)."""
        on = np.zeros(self.nv, bool)
        on[vertices] = True
        return np.concatenate([vertices, self.nv + np.nonzero(on[self.edges[:, 0]]
                                                              & on[self.edges[:, 1]])[0]])

    def gradients(self, dphi):
        return np.einsum("ka,tab->tkb", dphi, self.jinv)


STIFFNESS_POINTS = [(1 / 6, 1 / 6), (2 / 3, 1 / 6), (1 / 6, 2 / 3)]  # exact for degree 2


def shear_rates(mesh, u):
    """sqrt(2 eps:eps) at the stiffness's quadrature points, one column per point."""
    ul = np.stack([u[2 * mesh.p2], u[2 * mesh.p2 + 1]], -1)
    rates = []
    for xi, eta in STIFFNESS_POINTS:
        grad = np.einsum("tkc,tkb->tcb", ul, mesh.gradients(p2_shape(xi, eta)[2]))
        eps = 0.5 * (grad + np.transpose(grad, (0, 2, 1)))
        rates.append(np.sqrt(2.0 * np.einsum("tcb,tcb->t", eps, eps)))
    return np.stack(rates, -1)


def stokes_operators(mesh, mu):
    """Viscous stiffness 2 mu eps(u):eps(v) and divergence -q div v; mu a number or one value
    per triangle and quadrature point."""
    mu = np.broadcast_to(np.asarray(mu, float), (len(mesh.triangles), 3))
    rows, cols, vals, brows, bcols, bvals = [], [], [], [], [], []
    for q, (xi, eta) in enumerate(STIFFNESS_POINTS):
        l, _, dphi = p2_shape(xi, eta)
        g = mesh.gradients(dphi)
        w = (mesh.area / 3.0)[:, None, None]
        for c in range(2):
            for d in range(2):
                k = mu[:, q, None, None] * ((c == d) * np.einsum("tkb,tlb->tkl", g, g)
                                            + np.einsum("tk,tl->tkl", g[:, :, d], g[:, :, c])) * w
                rows.append(np.repeat(2 * mesh.p2 + c, 6, 1).ravel())
                cols.append(np.tile(2 * mesh.p2 + d, 6).ravel())
                vals.append(k.ravel())
            bk = -np.einsum("k,tl->tkl", l, g[:, :, c]) * w
            brows.append(np.repeat(mesh.triangles, 6, 1).ravel())
            bcols.append(np.tile(2 * mesh.p2 + c, 3).ravel())
            bvals.append(bk.ravel())
    n = 2 * len(mesh.nodes)
    stiffness = sp.csr_matrix((np.concatenate(vals), (np.concatenate(rows),
                                                      np.concatenate(cols))), (n, n))
    divergence = sp.csr_matrix((np.concatenate(bvals), (np.concatenate(brows),
                                                        np.concatenate(bcols))), (mesh.nv, n))
    return stiffness, divergence


def inertia(mesh, u, rho):
    """Residual and Jacobian of rho (u.grad u + 2 Omega z x u), the convection and Coriolis
    terms of steady flow in the frame turning with the body (the centrifugal term is a gradient,
    taken up by the pressure, and exerts no torque)."""
    n = 2 * len(mesh.nodes)
    ul = np.stack([u[2 * mesh.p2], u[2 * mesh.p2 + 1]], -1)  # (t, k, c)
    residual = np.zeros(n)
    rows, cols, vals = [], [], []
    coriolis = 2.0 * OMEGA * np.array([[0.0, -1.0], [1.0, 0.0]])
    points, weights = quadrature_degree5()
    for (xi, eta), wq in zip(points, weights):
        _, phi, dphi = p2_shape(xi, eta)
        g = mesh.gradients(dphi)
        w = rho * wq * 2.0 * mesh.area
        uq = np.einsum("k,tkc->tc", phi, ul)
        grad = np.einsum("tkc,tkb->tcb", ul, g)  # d u_c / d x_b
        force = np.einsum("tb,tcb->tc", uq, grad) + uq @ coriolis.T
        for c in range(2):
            np.add.at(residual, 2 * mesh.p2 + c, w[:, None] * phi[None, :] * force[:, c, None])
            for d in range(2):
                block = (np.einsum("k,l,t->tkl", phi, phi, grad[:, c, d] + coriolis[c, d])
                         + (c == d) * np.einsum("k,tl->tkl", phi, np.einsum("tb,tlb->tl", uq, g)))
                rows.append(np.repeat(2 * mesh.p2 + c, 6, 1).ravel())
                cols.append(np.tile(2 * mesh.p2 + d, 6).ravel())
                vals.append((w[:, None, None] * block).ravel())
    jacobian = sp.csr_matrix((np.concatenate(vals), (np.concatenate(rows),
                                                     np.concatenate(cols))), (n, n))
    return residual, jacobian


def torque(points, triangles, inner, outer, viscosity, rho):
    """Steady flow in the body's frame (body at rest, the circle turning at -omega) by Newton's
    method from the Stokes solution (rho = 0 gives Stokes flow), the viscosity (a function of
    the shear rate) lagged by one step (Picard) and each step's new one taken as the geometric
    mean with the last. Returns the torque per unit depth [N m / m] from the dissipation,
    T omega = int 2 mu eps(u):eps(u) dA (the power the outer wall gives the fluid in this frame,
    equal to the body's in the lab frame), and the number of steps."""
    mesh = Mesh(points, triangles)
    n = 2 * len(mesh.nodes)
    body, wall = mesh.boundary(inner), mesh.boundary(outer)
    u, p = np.zeros(n), np.zeros(mesh.nv)
    u[2 * wall], u[2 * wall + 1] = OMEGA * mesh.nodes[wall, 1], -OMEGA * mesh.nodes[wall, 0]
    fixed = np.zeros(n, bool)
    for k in (body, wall):
        fixed[2 * k] = fixed[2 * k + 1] = True
    free = np.nonzero(~fixed)[0]
    keep = np.arange(mesh.nv) != 0  # the pressure is pinned at one vertex
    mu = viscosity(np.full((len(mesh.triangles), 3), OMEGA))
    for step in range(200):
        stiffness, divergence = stokes_operators(mesh, mu)
        div = divergence[keep]
        residual, jacobian = inertia(mesh, u, rho) if rho > 0 and step > 0 else (0.0, None)
        operator = stiffness + jacobian if jacobian is not None else stiffness
        r_u = (stiffness @ u + residual + divergence.T @ p)[free]
        saddle = sp.bmat([[operator[free][:, free], div[:, free].T], [div[:, free], None]],
                         format="csc")
        delta = spla.spsolve(saddle, -np.concatenate([r_u, div @ u]))
        u[free] += delta[:len(free)]
        p[keep] += delta[len(free):]
        updated = np.sqrt(mu * viscosity(shear_rates(mesh, u)))
        change = np.abs(updated / mu - 1.0).max()
        mu = updated
        if change < 1e-6 and (rho == 0 or np.abs(delta[:len(free)]).max() < 1e-10 * OMEGA * R):
            break
    return u @ (stokes_operators(mesh, mu)[0] @ u) / OMEGA, step


def newtonian(mu):
    return lambda rate: np.full_like(rate, mu)


def power_law(consistency, index, lowest, highest):
    """K rate^(n - 1) within [lowest, highest], as partimix's power_law rheology."""
    return lambda rate: np.clip(consistency * np.maximum(rate, 1e-300)**(index - 1.0), lowest,
                                highest)


def flow_parameters(argv):
    """Viscosity and density: Stokes flow at the test's viscosity, or Re = rho N d^2 / mu with
    the test's density, N = 1 r/s and d = 2 A; or the CMC power law (cases/youcefi_vessel_cmc.yaml:
    K = 13.9 Pa s^n, n = 0.47, 0.1 to 40 Pa s) in Stokes flow or at the density given."""
    if len(argv) > 3 and argv[3] == "cmc":
        rho = float(argv[4]) if len(argv) > 4 else 0.0
        flow = f"CMC power law, rho = {rho:g}" if rho > 0 else "CMC power law, Stokes flow"
        return power_law(13.9, 0.47, 0.1, 40.0), rho, flow
    if len(argv) < 4:
        return newtonian(MU), 0.0, "Stokes flow"
    reynolds = float(argv[3])
    mu = RHO * (OMEGA / (2.0 * np.pi)) * (2.0 * A)**2 / reynolds
    return newtonian(mu), RHO, f"Re = {reynolds:g}"


def couette_torque(viscosity):
    """Torque per unit depth on the circle R1 turning in R: Newtonian 4 pi mu omega R1^2 R^2 /
    (R^2 - R1^2); power law 2 pi K (2 omega / (n (R1^(-2/n) - R^(-2/n))))^n (docs/power.md),
    told apart by the viscosity's response to the shear rate."""
    k_at_1, k_at_2 = viscosity(np.array([1.0, 2.0]))
    index = 1.0 + np.log2(k_at_2 / k_at_1)
    return 2.0 * np.pi * k_at_1 * (2.0 * OMEGA / (index * (R1**(-2.0 / index)
                                                             - R**(-2.0 / index))))**index


def main():
    body, n = sys.argv[1], int(sys.argv[2])
    viscosity, rho, flow = flow_parameters(sys.argv)
    if body == "plate":
        theta = plate_rays(n)
        result, steps = torque(*ray_mesh(theta, plate_radius(theta), n), viscosity, rho)
        print(f"plate {2 * A} x {2 * B} m in R = {R} m, {flow}, {n} rays a quarter: "
              f"{result:.4f} N m/m ({steps} steps)")
    else:
        theta = np.linspace(0.0, 2.0 * np.pi, 4 * n, endpoint=False)
        result, steps = torque(*ray_mesh(theta, np.full_like(theta, R1), n), viscosity, rho)
        exact = couette_torque(viscosity)
        print(f"circle R1 = {R1} m, {flow}, {n} rays a quarter: {result:.4f} N m/m, "
              f"exact {exact:.4f} ({result / exact - 1:+.2e}, {steps} steps)")


if __name__ == "__main__":
    main()
