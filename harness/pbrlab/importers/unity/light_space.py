"""Unity's world-to-light matrix (``unity_WorldToLight``; Unity 5.3 and earlier:
``_LightMatrix0``) for the light a built-in forward pass draws, as statements an entry point
runs (engine_inputs.FILLED and fill_statements call these), and the light textures beside it.

Unity's forward path (AutoLight.cginc, "Light cookies" and "Point light attenuation" in its
manual) maps a world position p through unity_WorldToLight and reads:

* a point light: ``dot(c, c)`` of c = unity_WorldToLight p, the squared distance over the
  range squared (the light's scale is its range: c = (p - position) / range), looked up in the
  attenuation texture _LightTexture0 (the point cookie a cube map);
* a spot light: c = (x, y, z, w) with the cookie at ``c.xy / c.w + 0.5`` (the cone's rim at
  +-0.5, its axis at the centre), ``c.z > 0`` in front of the light, and ``dot(c.xyz, c.xyz)``
  looked up in the attenuation texture _LightTextureB0; here x, y = 0.5 cot(outer half-angle)
  (l . right, l . up) / range, z = w = (l . axis) / range for l = p - position, the projection
  Unity's cookie documentation describes (a cookie spans the spot's cone);
* a directional light: its rotation (its cookie's plane; no cookie is read without one).

pbrlab's lights carry their falloff and cone in _LightColor0 at the shaded point already
(generate_pass._main_light; LIGHT_ATTENUATION is 1), so the attenuation and cookie textures a
program samples are white (1 everywhere: _LightTexture0, _LightTextureB0): a Unity Shaders Book
style forward-add pass computes ``_LightColor0 * tex2D(_LightTexture0, dot(c, c).rr).r`` =
pbrlab's attenuated light, as its LIGHT_ATTENUATION path does. A light's right and up (which only
a cookie would show) are any unit pair perpendicular to its axis: right = normalize(world up x
axis), or world x x axis where the axis is within 2.6 degrees of vertical.

    light_space.statements(name, language)   # the entry point's statements that fill ``name``
"""

from __future__ import annotations

from .properties import DEFAULT_TEXELS

# The textures Unity binds for a light's attenuation and cookie: white here (module doc).
LIGHT_TEXTURES = ("_LightTexture0", "_LightTextureB0")
# |axis . world up| above which the right vector is built from world x instead (cos 2.6 deg)
_VERTICAL = 0.999


def _matrix(rows: list[str], language: str) -> str:
    """A 4x4 matrix of 16 scalar expressions in row order, as the language builds it."""
    flat = ", ".join(rows)
    return f"float4x4({flat})" if language == "hlsl" else f"transpose(mat4({flat}))"


def statements(name: str, language: str) -> list[str]:
    """Lines that set the matrix global ``name`` to the pass's light's world-to-light matrix
    (module doc; the identity where the pass has no light)."""
    vec3 = "float3" if language == "hlsl" else "vec3"
    out = ["#if defined(PBRLAB_UNITY_ADD_POINT)", "    {",
           "        float pbrlab_s = 1.0 / u_point_range[PBRLAB_UNITY_ADD_POINT];",
           f"        {vec3} pbrlab_o = -pbrlab_s * u_point_position[PBRLAB_UNITY_ADD_POINT];",
           f"        {name} = " + _matrix(["pbrlab_s", "0.0", "0.0", "pbrlab_o.x", "0.0", "pbrlab_s", "0.0", "pbrlab_o.y",
                                          "0.0", "0.0", "pbrlab_s", "pbrlab_o.z", "0.0", "0.0", "0.0", "1.0"], language) + ";",
           "    }", "#elif defined(PBRLAB_UNITY_ADD_SPOT)", "    {",
           "        float pbrlab_s = 1.0 / u_spot_range[PBRLAB_UNITY_ADD_SPOT];",
           "        float pbrlab_c = u_spot_cone[PBRLAB_UNITY_ADD_SPOT].x;  // cos(outer half-angle)",
           "        float pbrlab_k = 0.5 * pbrlab_c / sqrt(max(1.0 - pbrlab_c * pbrlab_c, 1e-12)) * pbrlab_s;",
           f"        {vec3} pbrlab_z = normalize(u_spot_direction[PBRLAB_UNITY_ADD_SPOT]);",
           *_frame(vec3),
           f"        {vec3} pbrlab_p = u_spot_position[PBRLAB_UNITY_ADD_SPOT];",
           f"        {name} = " + _matrix([
               "pbrlab_k * pbrlab_x.x", "pbrlab_k * pbrlab_x.y", "pbrlab_k * pbrlab_x.z", "-pbrlab_k * dot(pbrlab_x, pbrlab_p)",
               "pbrlab_k * pbrlab_y.x", "pbrlab_k * pbrlab_y.y", "pbrlab_k * pbrlab_y.z", "-pbrlab_k * dot(pbrlab_y, pbrlab_p)",
               "pbrlab_s * pbrlab_z.x", "pbrlab_s * pbrlab_z.y", "pbrlab_s * pbrlab_z.z", "-pbrlab_s * dot(pbrlab_z, pbrlab_p)",
               "pbrlab_s * pbrlab_z.x", "pbrlab_s * pbrlab_z.y", "pbrlab_s * pbrlab_z.z", "-pbrlab_s * dot(pbrlab_z, pbrlab_p)"],
               language) + ";",
           "    }", "#elif defined(PBRLAB_UNITY_ADD_DIRECTIONAL) || PBRLAB_DIRECTIONAL_COUNT > 0", "    {",
           "#if defined(PBRLAB_UNITY_ADD_DIRECTIONAL)",
           f"        {vec3} pbrlab_z = normalize(u_directional_direction[PBRLAB_UNITY_ADD_DIRECTIONAL]);",
           "#else",
           f"        {vec3} pbrlab_z = normalize(u_directional_direction[0]);",
           "#endif",
           *_frame(vec3),
           f"        {name} = " + _matrix(["pbrlab_x.x", "pbrlab_x.y", "pbrlab_x.z", "0.0", "pbrlab_y.x", "pbrlab_y.y",
                                          "pbrlab_y.z", "0.0", "pbrlab_z.x", "pbrlab_z.y", "pbrlab_z.z", "0.0",
                                          "0.0", "0.0", "0.0", "1.0"], language) + ";",
           "    }", "#else",
           f"    {name} = " + _matrix(["1.0", "0.0", "0.0", "0.0", "0.0", "1.0", "0.0", "0.0", "0.0", "0.0", "1.0", "0.0",
                                     "0.0", "0.0", "0.0", "1.0"], language) + ";",
           "#endif"]
    return out


def _frame(vec3: str) -> list[str]:
    """The light's right (x) and up (y) perpendicular to its axis pbrlab_z (module doc)."""
    return [f"        {vec3} pbrlab_x = normalize(cross(abs(pbrlab_z.y) < {_VERTICAL} ? {vec3}(0.0, 1.0, 0.0) "
            f": {vec3}(1.0, 0.0, 0.0), pbrlab_z));",
            f"        {vec3} pbrlab_y = cross(pbrlab_z, pbrlab_x);"]


def bind(program, cache, unit: int) -> int:
    """White textures under LIGHT_TEXTURES where the program samples them (module doc); the
    texture units used."""
    from ...gpu.programs import set_uniform, uniforms_named
    used = 0
    for name in LIGHT_TEXTURES:
        if uniforms_named(program, name):
            cache.constant_texture(DEFAULT_TEXELS["white"]).use(unit + used)
            set_uniform(program, name, unit + used)
            used += 1
    return used
