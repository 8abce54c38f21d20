#!/usr/bin/python3
"""Reference torque for tests/validation/rotating_plate_test.cpp (docs/power.md, "The rotating
plate in 2D"): creeping (Stokes) flow between a rectangle of half-length a and half-width b
turning at omega about its centre and a circle of radius R at rest, by Taylor-Hood (P2-P1)
finite elements on a mesh of rays from the centre, graded towards the rectangle's corners and
towards both walls. The torque per unit depth follows from the dissipation,
T omega = int 2 mu eps(u):eps(u) dA, which for a rigid body is exactly the power it gives the
fluid. Check: with the rectangle replaced by a circle of radius R1 the script reproduces the
Couette torque 4 pi mu omega R1^2 R^2 / (R^2 - R1^2) (run with `circle`).

    tools/stokes_plate_reference.py plate N    # N rays per quarter turn (20, 40, 80)
    tools/stokes_plate_reference.py circle N

Needs numpy and scipy (python3-numpy, python3-scipy).
"""
import sys

import numpy as np
import scipy.sparse as sp
import scipy.sparse.linalg as spla

MU, OMEGA, R = 56.7, 2.0 * np.pi, 0.15  # Pa s, rad/s, m: the test's fluid, speed and vessel
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


def torque(points, triangles, inner, outer):
    """Solves the Stokes problem; returns the torque per unit depth [N m / m]."""
    nv = len(points)
    edges_all = np.sort(np.concatenate([triangles[:, [0, 1]], triangles[:, [1, 2]],
                                        triangles[:, [2, 0]]]), 1)
    edges, which = np.unique(edges_all, axis=0, return_inverse=True)
    mids = nv + which.reshape(3, -1).T
    nodes = np.vstack([points, 0.5 * (points[edges[:, 0]] + points[edges[:, 1]])])
    p2 = np.hstack([triangles, mids])
    x0, x1, x2 = (points[triangles[:, k]] for k in range(3))
    jac = np.stack([x1 - x0, x2 - x0], -1)
    area = 0.5 * np.abs(np.linalg.det(jac))
    jinv = np.linalg.inv(jac)
    rows, cols, vals, brows, bcols, bvals = [], [], [], [], [], []
    for xi, eta in [(1 / 6, 1 / 6), (2 / 3, 1 / 6), (1 / 6, 2 / 3)]:  # exact for degree 2
        l, _, dphi = p2_shape(xi, eta)
        g = np.einsum("ka,tab->tkb", dphi, jinv)
        w = (area / 3.0)[:, None, None]
        for c in range(2):  # 2 mu eps(u):eps(v), component blocks (c, d)
            for d in range(2):
                k = MU * ((c == d) * np.einsum("tkb,tlb->tkl", g, g)
                          + np.einsum("tk,tl->tkl", g[:, :, d], g[:, :, c])) * w
                rows.append(np.repeat(2 * p2 + c, 6, 1).ravel())
                cols.append(np.tile(2 * p2 + d, 6).ravel())
                vals.append(k.ravel())
            bk = -np.einsum("k,tl->tkl", l, g[:, :, c]) * w  # -q div v
            brows.append(np.repeat(triangles, 6, 1).ravel())
            bcols.append(np.tile(2 * p2 + c, 3).ravel())
            bvals.append(bk.ravel())
    n = 2 * len(nodes)
    stiffness = sp.csr_matrix((np.concatenate(vals), (np.concatenate(rows),
                                                      np.concatenate(cols))), (n, n))
    divergence = sp.csr_matrix((np.concatenate(bvals), (np.concatenate(brows),
                                                        np.concatenate(bcols))), (nv, n))

    def boundary(vertices):
        on = np.zeros(nv, bool)
        on[vertices] = True
        return np.concatenate([vertices, nv + np.nonzero(on[edges[:, 0]] & on[edges[:, 1]])[0]])

    body, wall = boundary(inner), boundary(outer)
    u = np.zeros(n)
    u[2 * body], u[2 * body + 1] = -OMEGA * nodes[body, 1], OMEGA * nodes[body, 0]
    fixed = np.zeros(n, bool)
    for k in (body, wall):
        fixed[2 * k] = fixed[2 * k + 1] = True
    free = np.nonzero(~fixed)[0]
    keep = np.arange(nv) != 0  # the pressure is pinned at one vertex
    saddle = sp.bmat([[stiffness[free][:, free], divergence[keep][:, free].T],
                      [divergence[keep][:, free], None]], format="csc")
    rhs = np.concatenate([-(stiffness[free] @ u), -(divergence[keep] @ u)])
    u[free] = spla.spsolve(saddle, rhs)[:len(free)]
    return u @ (stiffness @ u) / OMEGA


def main():
    body, n = sys.argv[1], int(sys.argv[2])
    if body == "plate":
        theta = plate_rays(n)
        result = torque(*ray_mesh(theta, plate_radius(theta), n))
        print(f"plate {2 * A} x {2 * B} m in R = {R} m, {n} rays a quarter: {result:.4f} N m/m")
    else:
        theta = np.linspace(0.0, 2.0 * np.pi, 4 * n, endpoint=False)
        result = torque(*ray_mesh(theta, np.full_like(theta, R1), n))
        exact = 4.0 * np.pi * MU * OMEGA * R1**2 * R**2 / (R**2 - R1**2)
        print(f"circle R1 = {R1} m, {n} rays a quarter: {result:.4f} N m/m, "
              f"exact {exact:.4f} ({result / exact - 1:+.2e})")


if __name__ == "__main__":
    main()
