#!/usr/bin/python3
"""Generate the procedural height maps and colour textures shipped in Data/.

Run with Debian's Python (it has VTK 9.1 and numpy):

    /usr/bin/python3 Data/make_textures.py

from any working directory.  All files are written next to this script and
are fully determined by the fixed seeds below (no downloads, no hand edits).

Conventions
-----------
* Arrays are indexed ``a[j, i]`` with ``j`` the VTK image row.  Row ``j = 0``
  is the *bottom* row of the picture (VTK lower-left origin; vtkPNGWriter
  writes VTK row 0 as the last/bottom row of the PNG).
* Texel centres are at ``u = (i + 0.5) / W``, ``v = (j + 0.5) / H``.
* Height maps: white = high.  16-bit files map [0, 1] to [0, 65535],
  8-bit files map [0, 1] to [0, 255].
* Every pattern except ``rivets_height.png`` is built only from functions that
  are periodic with period 1 in ``u`` and ``v`` (periodic lattice noise,
  torus distances, FFT blur), so the textures tile seamlessly.
"""

import os
import sys

import numpy as np
from vtkmodules.util import numpy_support
from vtkmodules.util.vtkConstants import VTK_UNSIGNED_CHAR, VTK_UNSIGNED_SHORT
from vtkmodules.vtkCommonDataModel import vtkImageData
from vtkmodules.vtkIOImage import vtkPNGWriter

OUT_DIR = os.path.dirname(os.path.abspath(__file__))


# ---------------------------------------------------------------------------
# Helpers
# ---------------------------------------------------------------------------

def texel_grid(width, height):
    """Texel-centre coordinates u, v in [0, 1), arrays of shape (height, width)."""
    u = (np.arange(width) + 0.5) / width
    v = (np.arange(height) + 0.5) / height
    return np.meshgrid(u, v)  # uu[j, i] = u_i, vv[j, i] = v_j


def periodic_value_noise(width, height, freq, rng):
    """Value noise on a freq x freq lattice that wraps around; range [0, 1]."""
    lattice = rng.random((freq, freq))
    x = (np.arange(width) + 0.5) / width * freq
    y = (np.arange(height) + 0.5) / height * freq
    x0 = np.floor(x).astype(int)
    y0 = np.floor(y).astype(int)
    fx = x - x0
    fy = y - y0
    sx = fx * fx * fx * (fx * (fx * 6 - 15) + 10)  # quintic fade
    sy = fy * fy * fy * (fy * (fy * 6 - 15) + 10)
    x0 %= freq
    y0 %= freq
    x1 = (x0 + 1) % freq
    y1 = (y0 + 1) % freq
    a = lattice[np.ix_(y0, x0)]
    b = lattice[np.ix_(y0, x1)]
    c = lattice[np.ix_(y1, x0)]
    d = lattice[np.ix_(y1, x1)]
    sx = sx[None, :]
    sy = sy[:, None]
    top = a + (b - a) * sx
    bot = c + (d - c) * sx
    return top + (bot - top) * sy


def periodic_fbm(width, height, base_freq, octaves, rng, gain=0.5):
    """Fractal sum of periodic value noise, normalised to roughly [-1, 1]."""
    total = np.zeros((height, width))
    amp = 1.0
    norm = 0.0
    freq = base_freq
    for _ in range(octaves):
        total += amp * (periodic_value_noise(width, height, freq, rng) * 2.0 - 1.0)
        norm += amp
        amp *= gain
        freq *= 2
    return total / norm


def periodic_blur(img, sigma_px):
    """Gaussian blur with wrap-around (FFT), keeps the result tileable."""
    h, w = img.shape[:2]
    ky = np.fft.fftfreq(h)[:, None]
    kx = np.fft.fftfreq(w)[None, :]
    kernel = np.exp(-2.0 * (np.pi * sigma_px) ** 2 * (kx * kx + ky * ky))
    if img.ndim == 2:
        return np.real(np.fft.ifft2(np.fft.fft2(img) * kernel))
    out = np.empty_like(img, dtype=float)
    for c in range(img.shape[2]):
        out[..., c] = np.real(np.fft.ifft2(np.fft.fft2(img[..., c]) * kernel))
    return out


def smoothstep(e0, e1, x):
    t = np.clip((x - e0) / (e1 - e0), 0.0, 1.0)
    return t * t * (3.0 - 2.0 * t)


def to_u16(h):
    return np.round(np.clip(h, 0.0, 1.0) * 65535.0).astype(np.uint16)


def to_u8(x):
    """[0, 1] floats (grey or RGB) to 8-bit."""
    return np.round(np.clip(x, 0.0, 1.0) * 255.0).astype(np.uint8)


def write_png(name, pixels):
    """Write pixels[j, i(, c)] with row j = 0 at the bottom of the picture."""
    pixels = np.ascontiguousarray(pixels)
    height, width = pixels.shape[:2]
    ncomp = 1 if pixels.ndim == 2 else pixels.shape[2]
    if pixels.dtype == np.uint16:
        vtk_type = VTK_UNSIGNED_SHORT
    elif pixels.dtype == np.uint8:
        vtk_type = VTK_UNSIGNED_CHAR
    else:
        raise TypeError("unsupported dtype %s" % pixels.dtype)

    image = vtkImageData()
    image.SetDimensions(width, height, 1)
    # VTK point index = i + j * width, i.e. C order of pixels[j, i].
    flat = pixels.reshape(width * height, ncomp) if ncomp > 1 else pixels.reshape(-1)
    scalars = numpy_support.numpy_to_vtk(flat, deep=1, array_type=vtk_type)
    scalars.SetName("PNGImage")
    image.GetPointData().SetScalars(scalars)

    path = os.path.join(OUT_DIR, name)
    writer = vtkPNGWriter()
    writer.SetCompressionLevel(9)
    writer.SetFileName(path)
    writer.SetInputData(image)
    writer.Write()
    if writer.GetErrorCode() != 0:
        raise RuntimeError("vtkPNGWriter failed for %s" % path)
    print("wrote %-20s %4dx%-4d %2d-bit %d-comp %8d bytes"
          % (name, width, height, 16 if vtk_type == VTK_UNSIGNED_SHORT else 8,
             ncomp, os.path.getsize(path)))


# ---------------------------------------------------------------------------
# Bricks: running bond, 4 courses x 2 bricks per tile
# ---------------------------------------------------------------------------

def make_bricks(size=512, seed=1234):
    rng = np.random.default_rng(seed)
    uu, vv = texel_grid(size, size)

    courses, per_row = 4, 2
    brick_w, brick_h = 1.0 / per_row, 1.0 / courses
    mortar = 0.06            # groove width, fraction of the tile period
    half_m = mortar / 2.0    # each brick loses half a joint on every side
    bevel = 0.03             # width of the rounded brick shoulder (UV)

    # Which brick, and the position inside its cell (UV units, cell centred).
    row = np.floor(vv * courses).astype(int)                    # 0..3
    xs = uu * per_row + 0.5 * (row % 2)                         # half-brick offset
    col = np.floor(xs).astype(int) % per_row                    # wraps -> seamless
    px = (xs - np.floor(xs) - 0.5) * brick_w
    py = (vv * courses - row - 0.5) * brick_h
    brick_id = row * per_row + col
    n_bricks = courses * per_row

    # Signed distance to the brick face (rounded box), negative inside.
    hx = brick_w / 2.0 - half_m
    hy = brick_h / 2.0 - half_m
    qx = np.abs(px) - (hx - bevel)
    qy = np.abs(py) - (hy - bevel)
    sdf = (np.hypot(np.maximum(qx, 0.0), np.maximum(qy, 0.0))
           + np.minimum(np.maximum(qx, qy), 0.0) - bevel)
    t = np.clip(-sdf / bevel, 0.0, 1.0)
    shoulder = np.sin(0.5 * np.pi * t)           # rounded (convex) bevel

    # Per-brick attributes.
    top = 0.84 + 0.06 * rng.uniform(-1.0, 1.0, n_bricks)
    tilt_x = 0.04 * rng.uniform(-1.0, 1.0, n_bricks)
    tilt_y = 0.04 * rng.uniform(-1.0, 1.0, n_bricks)
    tint = rng.uniform(-1.0, 1.0, (n_bricks, 3))
    bright = rng.uniform(0.80, 1.12, n_bricks)

    # Noise fields (all periodic).
    n_fine = periodic_fbm(size, size, 16, 4, rng)
    n_coarse = periodic_fbm(size, size, 4, 3, rng)
    n_grain = periodic_value_noise(size, size, 128, rng) * 2.0 - 1.0
    n_mortar = periodic_fbm(size, size, 32, 3, rng)

    face = (top[brick_id]
            + tilt_x[brick_id] * (px / hx)
            + tilt_y[brick_id] * (py / hy)
            + 0.030 * n_fine + 0.012 * n_grain)
    mortar_h = 0.025 + 0.02 * n_mortar              # lowest level, 0.005..0.045
    height = mortar_h + (face - mortar_h) * shoulder
    height = np.clip(height, 0.0, 1.0)

    # Colour.
    base = np.array([0.60, 0.24, 0.17])            # brick red
    brick_rgb = base[None, None, :] * bright[brick_id][..., None]
    brick_rgb = brick_rgb + tint[brick_id] * np.array([0.06, 0.03, 0.02])
    brick_rgb = brick_rgb * (1.0 + 0.10 * n_coarse + 0.10 * n_fine
                             + 0.06 * n_grain)[..., None]
    brick_rgb = brick_rgb * (0.78 + 0.22 * shoulder)[..., None]   # darker edges
    mortar_rgb = np.array([0.74, 0.73, 0.70])[None, None, :] * \
        (1.0 + 0.06 * n_mortar + 0.03 * n_grain)[..., None]
    # Anti-aliased mortar/brick boundary (1 texel).
    a = np.clip(0.5 - sdf * size, 0.0, 1.0)[..., None]
    color = mortar_rgb * (1.0 - a) + brick_rgb * a

    write_png("bricks_height.png", to_u16(height))
    write_png("bricks_color.png", to_u8(color))


# ---------------------------------------------------------------------------
# Stones: periodic Voronoi cobbles with dome profiles
# ---------------------------------------------------------------------------

def _torus_offsets(pts, uu, vv):
    """Minimum-image offsets (n, H, W) from every texel to every point."""
    dx = pts[:, 0, None, None] - uu[None]
    dy = pts[:, 1, None, None] - vv[None]
    dx -= np.round(dx)
    dy -= np.round(dy)
    return dx, dy


def make_stones(size=512, seed=4321, grid=6, lloyd_iterations=3):
    rng = np.random.default_rng(seed)
    uu, vv = texel_grid(size, size)

    # Jittered-grid feature points on the unit torus, then a few Lloyd
    # (centroidal Voronoi) steps so the cobbles are evenly sized and roundish.
    gi, gj = np.meshgrid(np.arange(grid), np.arange(grid))
    pts = np.stack([(gi.ravel() + 0.5 + rng.uniform(-0.4, 0.4, grid * grid)) / grid,
                    (gj.ravel() + 0.5 + rng.uniform(-0.4, 0.4, grid * grid)) / grid],
                   axis=1) % 1.0
    n = len(pts)
    for _ in range(lloyd_iterations):
        dx, dy = _torus_offsets(pts, uu, vv)
        nearest = np.argmin(dx * dx + dy * dy, axis=0)
        jj, ii = np.indices(nearest.shape)
        ox = -dx[nearest, jj, ii]          # texel - point, torus-wrapped
        oy = -dy[nearest, jj, ii]
        cnt = np.bincount(nearest.ravel(), minlength=n)
        mx = np.bincount(nearest.ravel(), ox.ravel(), minlength=n) / np.maximum(cnt, 1)
        my = np.bincount(nearest.ravel(), oy.ravel(), minlength=n) / np.maximum(cnt, 1)
        pts = (pts + np.stack([mx, my], axis=1)) % 1.0

    dx, dy = _torus_offsets(pts, uu, vv)
    d2 = dx * dx + dy * dy
    nearest = np.argmin(d2, axis=0)
    jj, ii = np.indices(nearest.shape)
    ax = dx[nearest, jj, ii]
    ay = dy[nearest, jj, ii]
    a2 = ax * ax + ay * ay
    # Exact distance to each Voronoi bisector: (|w_k|^2 - |w_a|^2) / (2 |w_k - w_a|),
    # combined with a smooth minimum so that the cell corners come out rounded.
    sep = np.hypot(dx - ax[None], dy - ay[None])
    with np.errstate(divide="ignore", invalid="ignore"):
        dist_bis = (d2 - a2[None]) / (2.0 * sep)
    dist_bis[nearest[None] == np.arange(n)[:, None, None]] = np.inf
    hard = np.min(dist_bis, axis=0)
    k = 0.012                                   # corner rounding radius (UV)
    edge = hard - k * np.log(np.sum(np.exp(-(dist_bis - hard[None]) / k), axis=0))
    del dx, dy, d2, sep, dist_bis

    # Per-cell in-radius (largest border distance inside the cell).
    inr = np.zeros(n)
    np.maximum.at(inr, nearest.ravel(), edge.ravel())
    inr_px = inr[nearest]
    r_centre = np.sqrt(a2)                     # distance to the cell's centroid

    gap = 0.006                               # half-width of the joint between stones
    t = np.clip((edge - gap) / (0.55 * (inr_px - gap)), 0.0, 1.0)
    shoulder = np.sqrt(1.0 - (1.0 - t) ** 2)   # quarter-circle rounded edge
    crown = 1.0 - 0.35 * np.clip(r_centre / (1.3 * inr_px), 0.0, 1.0) ** 2  # dome

    top = 0.82 + 0.10 * rng.uniform(-1.0, 1.0, n)
    n_fine = periodic_fbm(size, size, 16, 4, rng)
    n_grain = periodic_value_noise(size, size, 128, rng) * 2.0 - 1.0
    n_ground = periodic_fbm(size, size, 32, 3, rng)

    ground = 0.04 + 0.03 * n_ground
    stone = top[nearest] * crown + 0.025 * n_fine + 0.010 * n_grain
    height = ground + (stone - ground) * shoulder
    height = periodic_blur(height, 1.5)        # soften medial-axis creases
    height = np.clip(height, 0.0, 1.0)

    # Colour: grey/brown stones, dark sandy joints.
    grey = rng.uniform(0.42, 0.66, n)
    warm = rng.uniform(-0.05, 0.06, n)
    stone_rgb = np.stack([grey + warm, grey + 0.3 * warm, grey - 0.6 * warm], axis=-1)[nearest]
    stone_rgb = stone_rgb * (1.0 + 0.14 * n_fine + 0.08 * n_grain)[..., None]
    stone_rgb = stone_rgb * (0.60 + 0.40 * shoulder * crown)[..., None]
    ground_rgb = np.array([0.30, 0.26, 0.21])[None, None, :] * \
        (1.0 + 0.20 * n_ground + 0.10 * n_grain)[..., None]
    a = smoothstep(gap - 0.5 / size, gap + 1.5 / size, edge)[..., None]
    color = ground_rgb * (1.0 - a) + stone_rgb * a
    color = periodic_blur(color, 0.6)

    write_png("stones_height.png", to_u16(height))
    write_png("stones_color.png", to_u8(color))


# ---------------------------------------------------------------------------
# Waves: analytic, used to check sampling / orientation exactly
# ---------------------------------------------------------------------------

def make_waves(size=256):
    uu, vv = texel_grid(size, size)   # vv[j] = (j + 0.5) / size, j = 0 at bottom
    h = 0.5 + 0.25 * (np.sin(2.0 * np.pi * 2.0 * uu) + np.sin(2.0 * np.pi * 3.0 * vv))
    write_png("waves_height.png", to_u16(h))


# ---------------------------------------------------------------------------
# Rivets: flat plate, 4x4 hemispherical heads, thin diagonal scratch
# ---------------------------------------------------------------------------

def make_rivets(size=256, grid=4, radius_px=16.0):
    ii, jj = np.meshgrid(np.arange(size), np.arange(size))
    x = ii + 0.5
    y = jj + 0.5
    cell = size / grid
    cx = (np.floor(x / cell) + 0.5) * cell
    cy = (np.floor(y / cell) + 0.5) * cell
    r = np.hypot(x - cx, y - cy) / radius_px
    h = np.full((size, size), 0.5)
    inside = r < 1.0
    h[inside] = 0.5 + 0.5 * np.sqrt(1.0 - r[inside] ** 2)   # hemisphere, top = 1.0

    # Scratch: exactly 2 texels wide in every row and column, level 0, along the
    # diagonal i - j = 32 (mod size), i.e. half way between two rivet diagonals.
    diag = (ii - jj) % size
    h[(diag == size // 8) | (diag == size // 8 + 1)] = 0.0
    write_png("rivets_height.png", to_u8(h))


# ---------------------------------------------------------------------------
# Checker: 8x8 squares, two contrasting colours
# ---------------------------------------------------------------------------

def make_checker(size=256, squares=8):
    ii, jj = np.meshgrid(np.arange(size), np.arange(size))
    sq = size // squares
    parity = ((ii // sq) + (jj // sq)) % 2
    c0 = np.array([235, 140, 20], dtype=np.uint8)   # orange
    c1 = np.array([20, 50, 130], dtype=np.uint8)    # dark blue
    rgb = np.where(parity[..., None] == 0, c0, c1).astype(np.uint8)
    write_png("checker_color.png", rgb)


def main():
    make_bricks()
    make_stones()
    make_waves()
    make_rivets()
    make_checker()
    return 0


if __name__ == "__main__":
    sys.exit(main())
