"""Issue 38: the prefiltered environment as the shaders read it (textureLod at lod = level) against
the float64 brute force (pbrlab.maths.reference.prefilter), luminance error per level
at the poles, the u = 0 seam, around the brightest texel and at 400 random directions: relative
to the reference ("rel"), and relative to the local mean ("local": the error over the larger of
the reference and the roughness-1 reference in the same direction, the cosine-weighted mean
around it, so that a near-black direction beside a sun is not judged by its own darkness).
Usage: PYTHONPATH=harness python benchmarks/prefilter_accuracy.py ENV.exr [cube]"""
import sys, time
import moderngl
from pbrlab.gpu import gl, ibl, shaders, targets
from pbrlab.gpu.programs import template_source
import numpy as np, moderngl, OpenImageIO as oiio
from pbrlab.maths.reference import prefilter as ref

def load(path):
    b = oiio.ImageBuf(path); return np.asarray(b.get_pixels(oiio.FLOAT))[..., :3].astype(np.float64)

def ring(center, radius_deg, count):
    c = center / np.linalg.norm(center)
    a = np.array([1.0, 0, 0]) if abs(c[0]) < 0.9 else np.array([0, 0, 1.0])
    t = np.cross(c, a); t /= np.linalg.norm(t); b = np.cross(c, t)
    phi = np.arange(count) / count * 2 * np.pi
    r = np.radians(radius_deg)
    return np.cos(r) * c + np.sin(r) * (np.cos(phi)[:, None] * t + np.sin(phi)[:, None] * b)

def direction_sets(image):
    up, down = np.array([0, 1.0, 0]), np.array([0, -1.0, 0])
    poles = np.concatenate([up[None], down[None]] + [ring(p, r, 16) for p in (up, down) for r in (0.5, 2, 5, 10, 20)])
    el = np.radians(np.array([-60, -30, -5, 0, 5, 30, 60]))
    phis = np.radians(np.array([-1.0, -0.1, 0.0, 0.1, 1.0]))
    E, P = np.meshgrid(el, phis)
    seam = np.stack([np.cos(E) * np.sin(P), np.sin(E), -np.cos(E) * np.cos(P)], -1).reshape(-1, 3)
    h, w = image.shape[:2]
    j, i = np.unravel_index(image.sum(-1).argmax(), (h, w))
    sun = ref.equirect_direction((i + 0.5) / w, 1 - (j + 0.5) / h)
    suns = np.concatenate([sun[None]] + [ring(sun, r, 12) for r in (1, 3, 10, 30)])
    rng = np.random.default_rng(38)
    rnd = rng.normal(size=(400, 3)); rnd /= np.linalg.norm(rnd, axis=1, keepdims=True)
    return {"poles": poles, "seam": seam, "sun": suns, "random": rnd}

LOOKUP_EQUIRECT = """#version 330 core
#include "pbr/ibl/equirect.glsl"
uniform sampler2D u_env; uniform sampler2D u_dirs; uniform float u_lod; out vec4 o;
void main(){ vec3 d = texelFetch(u_dirs, ivec2(gl_FragCoord.xy), 0).xyz;
 o = vec4(textureLod(u_env, pbr_equirect_uv(d), u_lod).rgb, 1.0);} """
LOOKUP_CUBE = """#version 330 core
uniform samplerCube u_env; uniform sampler2D u_dirs; uniform float u_lod; out vec4 o;
void main(){ vec3 d = texelFetch(u_dirs, ivec2(gl_FragCoord.xy), 0).xyz;
 o = vec4(textureLod(u_env, d, u_lod).rgb, 1.0);} """
def lookup(ctx, tex, dirs, lod, cube):
    src = shaders.expand(LOOKUP_CUBE if cube else LOOKUP_EQUIRECT)
    prog = shaders.build_program(ctx, template_source("fullscreen.vert", {}), src)
    n = len(dirs)
    dt = ctx.texture((n, 1), 4, np.concatenate([dirs, np.zeros((n, 1))], 1).astype('f4').tobytes(), dtype='f4')
    dt.filter = (moderngl.NEAREST, moderngl.NEAREST)
    vao = ctx.vertex_array(prog, [])
    with targets.Target(ctx, (n, 1), "f32", depth=False) as t:
        t.use(); tex.use(0); dt.use(1)
        prog["u_env"].value = 0; prog["u_dirs"].value = 1; prog["u_lod"].value = float(lod)
        vao.render(moderngl.TRIANGLES, vertices=3)
        out = t.read()[0, :, :3].astype(np.float64)
    vao.release(); dt.release()
    return out

def main(path, cube=False):
    ctx = gl.shared_context() if hasattr(gl, 'shared_context') else gl.create_context(None)
    img = load(path)
    t0, w0 = time.process_time(), time.perf_counter()
    levels = ibl._prefilter_levels(ctx, img.astype(np.float32))  # uncached
    print(f"prefilter (uncached): process {time.process_time() - t0:.2f} s, wall {time.perf_counter() - w0:.2f} s")
    tex = ibl.float_cube_from_levels(ctx, levels)
    sets = direction_sets(img)
    L = ibl.PREFILTER_LEVELS
    lum = np.array([0.2126, 0.7152, 0.0722])
    cells2 = ref.quadrature_cells(img, 2)
    mean = {name: ref.prefiltered_radiance(img, dirs, 1.0, cells=cells2) @ lum for name, dirs in sets.items()}
    for level in range(L):
        r = level / (L - 1)
        cells = ref.quadrature_cells(img, 4) if 0 < r < 0.4 else cells2
        print(f"level {level} r={r:.2f} face {max(ibl.PREFILTER_FACE_SIZE >> level, 1)}", flush=True)
        for name, dirs in sets.items():
            want = ref.prefiltered_radiance(img, dirs, r, cells=cells)
            got = lookup(ctx, tex, dirs, level, cube)
            lw = want @ lum; lg = got @ lum
            rel = np.abs(lg - lw) / lw
            local = np.abs(lg - lw) / np.maximum(lw, mean[name])
            print(f"  {name:7s} rel max {rel.max():.3f} p99 {np.percentile(rel, 99):.3f}"
                  f" | local max {local.max():.3f} p99 {np.percentile(local, 99):.3f}", flush=True)

if __name__ == "__main__":
    main(sys.argv[1], len(sys.argv) > 2)
