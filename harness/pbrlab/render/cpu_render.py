"""The independent float64 CPU renderer for analytic scenes and untextured meshes.

Same camera rays (camera.camera_rays), ray-sphere intersection, lights and shading as
the GPU renderer, computed in float64 numpy with ``pbrlab.maths.reference`` instead of the
GLSL library. Goldens of analytic scenes are checked against it, and the goldens of the
layered glTF assets where their materials are untextured.

Meshes: ray-triangle intersection (Möller & Trumbore 1997) against the triangles in world
space, the normal and tangent interpolated barycentrically as the rasteriser interpolates
mesh.vert's outputs (normal matrix, model matrix), back faces of single-sided materials
culled. ``unmodelled="nan"`` renders a textured material's pixels as NaN instead of refusing
the scene, so a check compares the rest.

Scope: opaque spheres and meshes with the default surface (no texture maps; a clear coat along the
geometric normal; a sheen; an anisotropic base along the sphere's tangent; a thin film of
the maximum thickness; a transmission, thin or through a volume, that sees the scene's other
spheres over the constant environment: ``transmission_copy``); environments of
constant radiance, whose prefiltered radiance is that constant at every roughness. The
environment BRDF (A, B), which the split sum and the diffuse-specular coupling of every light
read, is the float64 integral of reference/directional_albedo.py at each pixel's exact
(NdotV, roughness); the GPU interpolates its 256 x 256 table (ibl.py) at every tier.
With ``render.brdf_model: unity`` the shading is the float64 transcription of Unity's
BRDF of the tier (pbrlab.maths.reference.unity_brdf), occlusion applied in the GI step.
"""

from __future__ import annotations

import numpy as np

from ..maths.camera import camera_rays
from ..scene.environment import environment_sh, sh_irradiance
from ..foundation.errors import PbrlabError
from ..maths.reference import clearcoat as ref_clearcoat
from ..maths.reference import sheen as ref_sheen
from ..maths.reference import lighting as ref_lighting
from ..maths.reference import directional_albedo as ref_albedo
from ..maths.reference import material as ref_material
from ..maths.reference import remap as ref_remap
from ..maths.reference import shading as ref_shading
from ..maths.reference import specular_extension as ref_specular
from ..maths.reference import surface as ref_surface
from ..maths.reference import transmission as ref_transmission
from ..maths.reference import unity_brdf as ref_unity


def _intersect(origin, d, centre, radius):
    """Nearest positive hit distance per ray (inf where missed); the discriminant as
    templates/surface_pixel.inc computes it (r^2 - |oc x d|^2)."""
    oc = origin - centre
    b = d @ oc
    q = np.cross(oc[None, None], d)  # |q|: the centre's distance from the ray
    disc = radius * radius - np.sum(q * q, axis=-1)
    h = np.sqrt(np.maximum(disc, 0.0))
    t = -b - h
    t = np.where(t > 0, t, -b + h)
    return np.where((disc >= 0) & (t > 0), t, np.inf)


def _light_terms(light, p):
    """Unit direction to the light and the radiance arriving at points p[..., 3]."""
    radiance = light.color * light.intensity
    if light.type == "directional":
        return np.broadcast_to(-light.direction, p.shape), np.broadcast_to(radiance, p.shape)
    to_light = light.position - p
    d2 = np.sum(to_light * to_light, axis=-1, keepdims=True)
    l = to_light / np.sqrt(np.maximum(d2, ref_lighting.MIN_LIGHT_DISTANCE_SQUARED))
    atten = ref_lighting.distance_attenuation(d2, light.range)
    if light.type == "spot":
        cos_outer = np.cos(np.radians(light.outer_cone_deg))
        cos_inner = np.cos(np.radians(light.inner_cone_deg))
        atten = atten * ref_lighting.spot_attenuation(
            l, light.direction, cos_outer, 1.0 / max(cos_inner - cos_outer, 1e-4))[..., None]
    return l, radiance * atten


def _energy_compensated(scene) -> bool:
    """PBR_ENERGY_COMPENSATION of the scene's programs: render.energy_compensation false turns it
    off in every tier; true leaves the tier's choice (pbr/shading/dispatch.glsl; LOW: off)."""
    return scene.render.energy_compensation and ref_shading.QUALITY_ENERGY_COMPENSATION[scene.render.quality.upper()]


def _surface(material):
    """(diffuse colour, f0, coat F0, perceptual roughness): the coat is the dielectric over
    the diffuse (the metallic workflow's dielectric F0, 0.04 unless the material gives its
    dielectric_specular; the specular colour in the specular one)."""
    if material.workflow == "metallic":
        coat_f0 = (np.full(3, ref_material.DIELECTRIC_F0) if material.dielectric_specular is None
                   else np.asarray(material.dielectric_specular, float))
        diffuse = ref_material.diffuse_from_metallic_dielectric(material.albedo, material.metallic, coat_f0)
        f0 = ref_material.f0_from_metallic_dielectric(material.albedo, material.metallic, coat_f0)
    else:
        diffuse = ref_material.diffuse_from_specular(material.albedo, material.specular)
        f0 = coat_f0 = material.specular
    rough = ref_remap.perceptual_roughness_from_smoothness(material.smoothness)
    return (np.asarray(diffuse, float), np.asarray(f0, float), np.asarray(coat_f0, float), float(rough))


def _unity_shading(scene, material, n, v, p, env_sh, quality):
    """Unity's LightingStandard[Specular] with the tier's BRDF: once for the environment (GI
    step: SH irradiance / pi and the constant radiance, both times occlusion; no light) and
    once per light (no indirect), summed in the GPU's order."""
    tier = ref_unity.TIER_BRDF[quality]
    if material.workflow == "metallic":
        def lit(*light_and_gi):
            return ref_unity.lighting_standard(material.albedo, np.full(len(n), material.metallic),
                                               np.full(len(n), material.smoothness), n, v, *light_and_gi, tier=tier)
    else:
        def lit(*light_and_gi):
            return ref_unity.lighting_standard_specular(material.albedo, material.specular,
                                                        np.full(len(n), material.smoothness), n, v,
                                                        *light_and_gi, tier=tier)
    color = np.zeros(p.shape)
    zero = np.zeros(p.shape)
    if env_sh is not None:
        sh_diffuse = np.maximum(sh_irradiance(env_sh, n), 0) / np.pi
        prefiltered = np.broadcast_to(scene.environment.color * scene.environment.intensity, p.shape)
        gi_diffuse, gi_specular = ref_unity.gi_indirect(sh_diffuse, prefiltered, np.full(len(n), material.occlusion))
        color += lit(zero, n, gi_diffuse, gi_specular)
    for light in scene.lights:
        l, radiance = _light_terms(light, p)
        color += lit(radiance, l, zero, zero)
    return color


UNMODELLED = ("raise", "nan")


def render_scene_cpu(scene, unmodelled: str = "raise") -> np.ndarray:
    """HxWx4 float64 radiance of an analytic scene, top row first (``unmodelled``: see the
    module's doc)."""
    from .depth_range import scene_frame

    if unmodelled not in UNMODELLED:
        raise ValueError(f"unmodelled={unmodelled!r}: expected one of {UNMODELLED}")
    if scene.environment is not None and scene.environment.color is None:
        raise PbrlabError("the CPU reference handles constant environments only")
    for name, material in scene.materials.items():
        if material.surface or material.source is not None or material.alpha_mode != "opaque" or (
                material.textures and unmodelled == "raise"):
            raise PbrlabError(f"material {name}: the CPU reference renders opaque, untextured "
                              "materials with the default surface")
    quality = scene.render.quality.upper()
    frame = scene_frame(scene)
    d = camera_rays(frame)
    origin = frame.position
    out = np.zeros(d.shape[:2] + (4,))  # alpha 0 where nothing is hit, as on the GPU
    if not scene.objects:
        return out
    copy = transmission_copy(scene, unmodelled)
    hits, nearest, t = _nearest_hits(scene, origin, d)
    env_sh = environment_sh(scene.environment) if scene.environment is not None else None
    for index, (obj, hit) in enumerate(zip(scene.objects, hits)):
        mask = (nearest == index) & np.isfinite(t)
        if not mask.any():
            continue
        material = scene.materials[obj.material]
        if material.textures:  # unmodelled == "nan"
            out[mask] = np.nan
            continue
        dm = d[mask]
        p = origin + t[mask][:, None] * dm
        n, tangent = hit.frame(mask, p)
        v = -dm
        color = np.broadcast_to(material.emission, p.shape).copy()
        if scene.render.brdf_model == "unity":
            out[mask, :3] = color + _unity_shading(scene, material, n, v, p, env_sh, quality)
            out[mask, 3] = 1.0
            continue
        diffuse, f0, coat_f0, rough = _surface(material)
        r = float(ref_shading.clamp_perceptual_roughness(rough, quality))
        NdotV = np.maximum(np.sum(n * v, axis=-1), ref_shading.MIN_NDOTV)
        coat_f90, f90 = _explicit_f90s(material)
        if material.iridescence > 0.0:  # the film: the base's F0 and its coat's F0 per pixel
            film = (material.iridescence, material.iridescence_ior, material.iridescence_thickness_max)
            if f90 is None:
                f0 = ref_surface.iridescent_f0(np.broadcast_to(f0, p.shape), NdotV, *film)
                film_coat_f0 = ref_surface.iridescent_f0(np.broadcast_to(coat_f0, p.shape), NdotV, *film)
            else:  # the film over F0 / F90, scaled by F90 (KHR_materials_specular with _iridescence)
                f0 = ref_specular.iridescent_f0_f90(np.broadcast_to(f0, p.shape), np.full(NdotV.shape, f90),
                                                    NdotV, *film)
                film_coat_f0 = ref_specular.iridescent_f0_f90(np.broadcast_to(coat_f0, p.shape),
                                                              np.full(NdotV.shape, coat_f90), NdotV, *film)
            diffuse = ref_surface.iridescent_diffuse_color(diffuse, coat_f0, film_coat_f0)
            coat_f0 = film_coat_f0
        dfg = ref_albedo.split_sum_terms_at_alpha(NdotV, r * r)
        specular_f = material.brdf.get("specular_f") or ref_shading.QUALITY_DEFAULT_F[quality]
        transmitted = None
        if material.transmission > 0.0:  # part of the diffuse's weight passes through instead
            transmitted = (diffuse, dict(
                dfg=dfg, factor=material.transmission, thickness=material.thickness,
                attenuation_color=material.attenuation_color, attenuation_distance=material.attenuation_distance,
                ior=material.ior, quality=quality, specular_f=specular_f,
                energy_compensated=_energy_compensated(scene), coat_f90=coat_f90))
            diffuse = ref_surface.transmission_diffuse_color(diffuse, material.transmission)
        direct_diffuse = ref_surface.coupled_diffuse_color(
            diffuse, coat_f0, ref_surface.specular_albedo_bound(coat_f0, dfg, specular_f, coat_f90))
        direction = (_sphere_anisotropy_direction(n, material.anisotropy_rotation) if tangent is None
                     else _anisotropy_direction(n, tangent, material.anisotropy_rotation))
        for light in scene.lights:
            l, radiance = _light_terms(light, p)
            if material.anisotropy_strength > 0.0:  # the base's lobe stretched (no indirect here)
                zero = np.zeros(p.shape)
                color += ref_surface.lighting_anisotropic(
                    diffuse, f0, coat_f0, rough, material.occlusion, n, v, l, radiance, zero, zero, dfg,
                    material.anisotropy_strength, direction, quality=quality, f90=f90, coat_f90=coat_f90,
                    **material.brdf)
                continue
            color += ref_shading.shade_punctual(n, v, l, radiance, direct_diffuse, f0, rough,
                                                quality=quality, f90=f90, **material.brdf)
        if transmitted is not None:  # each light through the surface, then the environment seen through it
            whole_diffuse, terms = transmitted
            zero = np.zeros(p.shape)
            color += transmitted_light(scene, material, n, v, p)
            if env_sh is not None or copy is not None:
                behind = _seen_through(scene, frame, copy, material, p, n, v)
                color += ref_surface.lighting_transmission(whole_diffuse, coat_f0, rough, material.occlusion, n, v,
                                                           n, zero, behind, **terms)
        if env_sh is not None:
            compensated = _energy_compensated(scene)
            indirect_diffuse = ref_surface.coupled_diffuse_color(
                diffuse, coat_f0, ref_surface.indirect_specular_albedo(coat_f0, dfg, compensated, coat_f90))
            color += indirect_diffuse / np.pi * np.maximum(sh_irradiance(env_sh, n), 0) * material.occlusion
            prefiltered = scene.environment.color * scene.environment.intensity
            color += ref_surface.indirect_specular_split_sum(
                np.broadcast_to(prefiltered, p.shape), f0, r, NdotV, material.occlusion, dfg,
                energy_compensated=compensated, f90=f90, quality=quality)
        if max(material.sheen_color) > 0.0:  # the sheen on the base, not on its emission
            emission = np.broadcast_to(material.emission, p.shape)
            color = emission + _sheened(scene, material, color - emission, n, v, p)
        if material.clearcoat > 0.0:
            color = _coated(scene, material, color, n, v, p, quality)
        out[mask, :3] = color
        out[mask, 3] = 1.0  # opaque: coverage
    return out


def transmitted_fraction(scene, material, n, v) -> np.ndarray:
    """[..., 3] float64: the fraction of the radiance seen through ``material`` (at normals n,
    views v) that reaches the camera: pbrlab.maths.reference.surface.lighting_transmission with a
    transmitted radiance of 1 and no light, rho (1 - E_spec) x transmission x Beer-Lambert
    over the thickness. A base without coat, sheen or film (the layers over it change what
    leaves the surface, which this fraction leaves out)."""
    if material.clearcoat > 0.0 or max(material.sheen_color) > 0.0 or material.iridescence > 0.0:
        raise PbrlabError("transmitted_fraction: a transmissive base without a coat, sheen or film")
    quality = scene.render.quality.upper()
    n, v = np.asarray(n, float).reshape(-1, 3), np.asarray(v, float).reshape(-1, 3)
    diffuse, _, coat_f0, rough = _surface(material)
    r = float(ref_shading.clamp_perceptual_roughness(rough, quality))
    NdotV = np.maximum(np.sum(n * v, axis=-1), ref_shading.MIN_NDOTV)
    dfg = ref_albedo.split_sum_terms_at_alpha(NdotV, r * r)
    zero = np.zeros(n.shape)
    return ref_surface.lighting_transmission(
        diffuse, coat_f0, rough, material.occlusion, n, v, n, zero, np.ones(n.shape), dfg,
        factor=material.transmission, thickness=material.thickness, attenuation_color=material.attenuation_color,
        attenuation_distance=material.attenuation_distance, ior=material.ior, quality=quality,
        specular_f=material.brdf.get("specular_f") or ref_shading.QUALITY_DEFAULT_F[quality],
        energy_compensated=_energy_compensated(scene), coat_f90=material.specular_f90)


def _explicit_f90s(material) -> tuple:
    """(coat_f90, f90): a material's explicit F90s, or (None, None) where F90 follows F0. The
    coat's (the dielectric's: KHR_materials_specular's dielectric_f90 = specular) and the
    surface's, which the metallic workflow blends towards 1 (F90 = mix(dielectric_f90, 1,
    metallic), the extension's "Implementation"; pbr_f90_from_metallic)."""
    coat_f90 = f90 = material.specular_f90
    if f90 is not None and material.workflow == "metallic":
        f90 = ref_material.f90_from_metallic(coat_f90, material.metallic)
    return coat_f90, f90


def environment_reflected(scene, material, n, v) -> np.ndarray:
    """[..., 3] float64: what the scene's constant environment adds off ``material``'s base at
    normals n, views v, as render_scene_cpu adds it: the coupled diffuse (the transmission's
    share taken out) times the SH irradiance / pi and occlusion, plus the split sum (f0 A +
    F90 B, the material's explicit F90 where it has one, times the energy compensation where
    the scene applies it, and the specular occlusion). A base without coat, sheen, film or
    anisotropy, whose light through the surface (transmitted_fraction) is counted apart."""
    if material.clearcoat > 0.0 or max(material.sheen_color) > 0.0 or material.iridescence > 0.0 \
            or material.anisotropy_strength > 0.0:
        raise PbrlabError("environment_reflected: a base without a coat, sheen, film or anisotropy")
    quality = scene.render.quality.upper()
    n, v = np.asarray(n, float).reshape(-1, 3), np.asarray(v, float).reshape(-1, 3)
    diffuse, f0, coat_f0, rough = _surface(material)
    r = float(ref_shading.clamp_perceptual_roughness(rough, quality))
    NdotV = np.maximum(np.sum(n * v, axis=-1), ref_shading.MIN_NDOTV)
    dfg = ref_albedo.split_sum_terms_at_alpha(NdotV, r * r)
    compensated = _energy_compensated(scene)
    coat_f90, f90 = _explicit_f90s(material)
    diffuse = ref_surface.transmission_diffuse_color(diffuse, material.transmission)
    coupled = ref_surface.coupled_diffuse_color(
        diffuse, coat_f0, ref_surface.indirect_specular_albedo(coat_f0, dfg, compensated, coat_f90))
    irradiance = np.maximum(sh_irradiance(environment_sh(scene.environment), n), 0)
    prefiltered = np.broadcast_to(scene.environment.color * scene.environment.intensity, n.shape)
    return coupled / np.pi * irradiance * material.occlusion + ref_surface.indirect_specular_split_sum(
        prefiltered, np.broadcast_to(f0, n.shape), r, NdotV, material.occlusion, dfg,
        energy_compensated=compensated, f90=f90, quality=quality)


def transmitted_light(scene, material, n, v, p) -> np.ndarray:
    """[..., 3] float64: the scene's lights seen through ``material``'s base at the points p
    (normals n, views v), as render_scene_cpu adds them to the base (before a coat or sheen
    over it changes what leaves): pbrlab.maths.reference.surface.lighting_transmission of each light
    with nothing behind, summed."""
    quality = scene.render.quality.upper()
    n, v, p = (np.asarray(x, float).reshape(-1, 3) for x in (n, v, p))
    diffuse, _, coat_f0, rough = _surface(material)
    r = float(ref_shading.clamp_perceptual_roughness(rough, quality))
    dfg = ref_albedo.split_sum_terms_at_alpha(np.maximum(np.sum(n * v, axis=-1), ref_shading.MIN_NDOTV), r * r)
    zero = np.zeros(n.shape)
    total = np.zeros(n.shape)
    for light in scene.lights:
        l, radiance = _light_terms(light, p)
        total += ref_surface.lighting_transmission(
            diffuse, coat_f0, rough, material.occlusion, n, v, l, radiance, zero, dfg,
            factor=material.transmission, thickness=material.thickness, attenuation_color=material.attenuation_color,
            attenuation_distance=material.attenuation_distance, ior=material.ior, quality=quality,
            specular_f=material.brdf.get("specular_f") or ref_shading.QUALITY_DEFAULT_F[quality],
            energy_compensated=_energy_compensated(scene), coat_f90=material.specular_f90)
    return total


def _nearest_hits(scene, origin, d):
    """Every object's hit along the rays d, the index of the nearest (argmin) and its distance
    (inf where nothing is hit)."""
    hits = [_sphere_hit(origin, d, obj) if obj.sphere is not None else _mesh_hit(origin, d, obj, scene)
            for obj in scene.objects]
    ts = np.stack([hit.t for hit in hits])
    return hits, np.argmin(ts, axis=0), np.min(ts, axis=0)


def visible_surfaces(scene) -> dict:
    """What each pixel's camera ray (camera.camera_rays, as render_scene_cpu) meets first:
    ``object`` (HxW int, the index in scene.objects, -1 for nothing), and HxWx3 float64 ``p``
    (the point), ``n`` (the unit normal: a sphere's, or a mesh's vertex normals interpolated as
    the rasteriser interpolates them), ``v`` (the unit view) and HxWx2 ``uv`` (a mesh's
    TEXCOORD_0 interpolated the same way), NaN where the ray meets nothing (uv: and on
    spheres). For checks that model a term per pixel next to a renderer's image."""
    from .depth_range import scene_frame

    frame = scene_frame(scene)
    d = camera_rays(frame)
    shape = d.shape[:2]
    out = {"object": np.full(shape, -1), "p": np.full(shape + (3,), np.nan), "n": np.full(shape + (3,), np.nan),
           "v": np.full(shape + (3,), np.nan), "uv": np.full(shape + (2,), np.nan)}
    if not scene.objects:
        return out
    hits, nearest, t = _nearest_hits(scene, frame.position, d)
    for index, hit in enumerate(hits):
        mask = (nearest == index) & np.isfinite(t)
        if not mask.any():
            continue
        p = frame.position + t[mask][:, None] * d[mask]
        out["object"][mask] = index
        out["p"][mask], out["n"][mask], out["v"][mask] = p, hit.frame(mask, p)[0], -d[mask]
        if hit.texcoord is not None:
            out["uv"][mask] = hit.texcoord(mask)
    return out


def _transmits(material) -> bool:
    return material.transmission > 0.0


def transmission_copy(scene, unmodelled: str = "raise") -> np.ndarray | None:
    """The scene a transmissive sphere sees (as transmission_copy.py draws it on the GPU): the
    float64 render of every sphere whose material does not transmit, radiance x coverage and
    coverage; None when no sphere transmits."""
    import dataclasses

    if not any(_transmits(scene.materials[o.material]) for o in scene.objects):
        return None
    behind = [o for o in scene.objects if not _transmits(scene.materials[o.material])]
    return render_scene_cpu(dataclasses.replace(scene, objects=behind), unmodelled)


def _seen_through(scene, frame, copy, material, p, n, v):
    """What a transmissive pixel sees (templates/transmission_scene.inc): along the
    transmitted direction d (-v thin-walled, refracted into a volume: reference/transmission.py
    refraction_direction), the point p + d · thickness projected by the camera, the copy read
    there bilinearly at its finest level, over the constant environment: copy.rgb + (1 -
    copy.a) · environment, the environment alone off screen. The GPU reads the copy's mip
    level log2(max(width, height)) · perceptual roughness, a blur of about 2^level pixels: the
    two agree where the copy is uniform over that blur, not at its edges."""
    environment = np.zeros(p.shape)
    if scene.environment is not None:
        environment = np.broadcast_to(np.asarray(scene.environment.color, float) * scene.environment.intensity, p.shape)
    if copy is None:
        return environment
    if material.thickness > 0.0:
        d = ref_transmission.refraction_direction(n, v, np.full(len(n), material.ior))
    else:
        d = -v
    exit_point = p + d * material.thickness
    clip = np.concatenate([exit_point, np.ones((len(p), 1))], axis=-1) @ frame.view_proj.T
    w = clip[:, 3]
    uv = clip[:, :2] / np.maximum(w, np.finfo(np.float32).tiny)[:, None] * 0.5 + 0.5
    on_screen = (w > 0) & np.all((uv >= 0.0) & (uv <= 1.0), axis=-1)
    height, width = copy.shape[:2]
    # texel coordinates of the top-row-first copy: texel centres at integers
    x = np.clip(uv[:, 0] * width - 0.5, 0.0, width - 1.0)
    y = np.clip((1.0 - uv[:, 1]) * height - 0.5, 0.0, height - 1.0)
    x0, y0 = np.floor(x).astype(int), np.floor(y).astype(int)
    x1, y1 = np.minimum(x0 + 1, width - 1), np.minimum(y0 + 1, height - 1)
    fx, fy = (x - x0)[:, None], (y - y0)[:, None]
    texel = ((copy[y0, x0] * (1 - fx) + copy[y0, x1] * fx) * (1 - fy)
             + (copy[y1, x0] * (1 - fx) + copy[y1, x1] * fx) * fy)
    seen = texel[:, :3] + (1.0 - np.clip(texel[:, 3:], 0.0, 1.0)) * environment
    return np.where(on_screen[:, None], seen, environment)


class _Hit:
    """One object's nearest hit distance per ray (inf where missed) and ``frame(mask, p)``:
    the unit normal and the tangent (xyz, w; None for a sphere) at the hit points p of the
    rays in ``mask``; on a mesh ``texcoord(mask)``: TEXCOORD_0 there (None on a sphere)."""

    def __init__(self, t, frame, texcoord=None):
        self.t, self.frame, self.texcoord = t, frame, texcoord


def _sphere_hit(origin, d, obj):
    centre, radius = obj.sphere

    def frame(mask, p):
        n = p - centre
        return n / np.linalg.norm(n, axis=-1, keepdims=True), None
    return _Hit(_intersect(origin, d, centre, radius), frame)


# Möller & Trumbore 1997: a determinant below this (|edge1 x edge2| in units of the scene
# squared, times the ray's sine) is a ray parallel to the triangle: no hit.
_PARALLEL_DETERMINANT = 1e-12


def _mesh_hit(origin, d, obj, scene):
    """The nearest front-facing (any facing for a double-sided material) triangle along each
    ray (Möller & Trumbore 1997, "Fast, minimum storage ray-triangle intersection"), with its
    barycentric coordinates; the frame interpolates the vertex normals (through the normal
    matrix) and tangents (through the model matrix) as the rasteriser does."""
    from ..scene import meshes

    positions, normals, texcoords, tangents, indices = meshes.mesh_data(obj).arrays[:5]
    m = np.asarray(obj.transform, float)
    world = np.asarray(positions, float) @ m[:3, :3].T + m[:3, 3]
    tri = np.asarray(indices).reshape(-1, 3)
    material = scene.materials[obj.material]
    two_sided = bool(material.double_sided)
    # only the rays that meet the mesh's bounding sphere are tested against its triangles
    lo, hi = world.min(axis=0), world.max(axis=0)
    centre = (lo + hi) / 2
    bound = float(np.linalg.norm(world - centre, axis=-1).max()) * (1 + 1e-9) + 1e-12
    near = np.isfinite(_intersect(origin, d, centre, bound)).reshape(-1) | bool(
        np.linalg.norm(origin - centre) <= bound)
    rays = d.reshape(-1, 3)[near]
    best_t = np.full(len(rays), np.inf)
    best = np.zeros((len(rays), 3))  # triangle, u, v of the nearest hit
    for k, (a, b, c) in enumerate(world[tri]):
        e1, e2 = b - a, c - a
        pvec = np.cross(rays, e2)
        det = pvec @ e1
        facing = det > _PARALLEL_DETERMINANT if not two_sided else np.abs(det) > _PARALLEL_DETERMINANT
        inv = np.where(facing, 1.0 / np.where(facing, det, 1.0), 0.0)
        tvec = origin - a
        u = (pvec @ tvec) * inv
        qvec = np.cross(tvec, e1)
        v = (rays @ qvec) * inv
        t = (qvec @ e2) * inv
        hit = facing & (u >= 0) & (v >= 0) & (u + v <= 1) & (t > 0) & (t < best_t)
        best_t = np.where(hit, t, best_t)
        best[hit] = np.stack([np.full(hit.sum(), k), u[hit], v[hit]], axis=-1)
    normal_matrix = np.linalg.inv(m[:3, :3]).T
    every_t = np.full(near.shape, np.inf)
    every_t[near] = best_t
    every = np.zeros((len(near), 3))
    every[near] = best

    def barycentric(mask):
        chosen = every[mask.reshape(-1)]
        weights = np.stack([1 - chosen[:, 1] - chosen[:, 2], chosen[:, 1], chosen[:, 2]], axis=-1)
        return tri[chosen[:, 0].astype(int)], weights

    def texcoord(mask):
        corners, weights = barycentric(mask)
        return np.einsum("rk,rkc->rc", weights, np.asarray(texcoords, float)[corners])

    def frame(mask, p):
        corners, weights = barycentric(mask)
        n = np.einsum("rk,rkc->rc", weights, np.asarray(normals, float)[corners]) @ normal_matrix.T
        n /= np.linalg.norm(n, axis=-1, keepdims=True)
        tangent = np.einsum("rk,rkc->rc", weights, np.asarray(tangents, float)[corners])
        tangent[:, :3] = tangent[:, :3] @ m[:3, :3].T
        return n, tangent
    return _Hit(every_t.reshape(d.shape[:2]), frame, texcoord)


def _anisotropy_direction(n, tangent, rotation):
    """The anisotropy's world direction on a mesh (no map): the interpolated tangent made
    orthogonal to n (Gram-Schmidt, as templates/scene_lighting.inc
    pbrlab_tangent_to_world_normal; bitangent n x t times the sign of w) rotated by
    ``rotation`` radians towards the bitangent (KHR_materials_anisotropy)."""
    t = tangent[:, :3] - n * np.sum(n * tangent[:, :3], axis=-1, keepdims=True)
    t /= np.linalg.norm(t, axis=-1, keepdims=True)
    b = np.cross(n, t) * np.where(tangent[:, 3:] < 0.0, -1.0, 1.0)
    d = t * np.cos(rotation) + b * np.sin(rotation)
    return d / np.linalg.norm(d, axis=-1, keepdims=True)


def _sphere_anisotropy_direction(n, rotation):
    """The anisotropy's world direction on a sphere (no map): the sphere's tangent along
    increasing u (templates/scene_geometry.inc pbrlab_sphere_tangent: (cos φ, 0, sin φ),
    φ = 2π u the azimuth of pbr_equirect_uv, bitangent n x t) rotated by ``rotation`` radians
    towards the bitangent (KHR_materials_anisotropy). The constant environment makes the bent
    normal irrelevant here: the prefiltered radiance is the same along every direction."""
    phi = np.arctan2(n[:, 0], -n[:, 2])
    t = np.stack([np.cos(phi), np.zeros_like(phi), np.sin(phi)], axis=-1)
    b = np.cross(n, t)
    d = t * np.cos(rotation) + b * np.sin(rotation)
    return d / np.linalg.norm(d, axis=-1, keepdims=True)


def _coated(scene, material, base, n, v, p, quality):
    """The clear coat over everything the base reflects and emits (reference/clearcoat.py):
    base · weight + mask · (each light's coat lobe + the constant environment times E_coat),
    the coat along the geometric normal (no coat normal map in this renderer's scope)."""
    rough = float(ref_shading.clamp_perceptual_roughness(
        ref_remap.perceptual_roughness_from_smoothness(material.clearcoat_smoothness), quality))
    NcdotV = np.maximum(np.sum(n * v, axis=-1), ref_shading.MIN_NDOTV)
    dfg = ref_albedo.split_sum_terms_at_alpha(NcdotV, rough * rough)
    coat = np.zeros(p.shape)
    for light in scene.lights:
        l, radiance = _light_terms(light, p)
        coat += ref_clearcoat.clearcoat_punctual(n, v, l, radiance, rough, quality=quality)
    if scene.environment is not None:
        prefiltered = scene.environment.color * scene.environment.intensity
        coat += np.asarray(prefiltered, float) * (ref_clearcoat.clearcoat_albedo(dfg) * ref_surface.specular_occlusion(
            NcdotV, material.occlusion, rough * rough, quality))[:, None]
    weight = ref_clearcoat.clearcoat_base_weight(material.clearcoat, NcdotV, dfg)
    return base * weight[:, None] + material.clearcoat * coat


def _sheen_albedo(NdotV, rough):
    """E(NdotV) of the white sheen at this roughness: the float64 quadrature of
    sheen_table.integrate_sheen_albedo on 257 views log-spaced over [PBR_MIN_NDOTV, 1] at the
    exact roughness, interpolated linearly in log NdotV (the GPU reads the 128 x 128 table)."""
    from ..gpu.sheen_table import integrate_sheen_albedo
    mu = np.geomspace(ref_shading.MIN_NDOTV, 1.0, 257)
    E = integrate_sheen_albedo(mu, np.full_like(mu, rough))
    return np.interp(np.log(np.clip(NdotV, ref_shading.MIN_NDOTV, 1.0)), np.log(mu), E)


def _sheened(scene, material, base, n, v, p):
    """KHR_materials_sheen's sheen over the base (reference/sheen.py lighting_sheen): base ·
    (1 - max3(c) E') + each light's sheen lobe + the constant environment times c E'."""
    rough = float(ref_remap.perceptual_roughness_from_smoothness(material.sheen_smoothness))
    NdotV = np.maximum(np.sum(n * v, axis=-1), ref_shading.MIN_NDOTV)
    E = _sheen_albedo(NdotV, rough)
    color = np.asarray(material.sheen_color, float)
    zero = np.zeros(p.shape)
    sheen = np.zeros(p.shape)
    for light in scene.lights:
        l, radiance = _light_terms(light, p)
        sheen += ref_sheen.lighting_sheen(zero, color, rough, n, v, l, radiance, zero, 0.0, E)
    prefiltered = zero
    if scene.environment is not None:
        prefiltered = np.broadcast_to(np.asarray(scene.environment.color, float) * scene.environment.intensity, p.shape)
    return ref_sheen.lighting_sheen(base, color, rough, n, v, n, zero, prefiltered, material.occlusion, E) + sheen
