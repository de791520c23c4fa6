"""Small GL helpers shared by the harness tests: a fullscreen pass over one texture."""

from importlib import resources

from pbrlab.gpu import shaders


def fullscreen_program(ctx, fragment_body: str, name: str = "<test.frag>", include_dirs=()):
    """A program drawing one fullscreen triangle with the given fragment shader text."""
    vert = resources.files("pbrlab").joinpath("templates", "fullscreen.vert").read_text()
    program = shaders.build_program(
        ctx, shaders.expand(vert, "<fullscreen.vert>"),
        shaders.expand(fragment_body, name, include_dirs=include_dirs))
    return program, ctx.vertex_array(program, [])


COPY_TEXELS = """#version 330 core
uniform sampler2D source;
out vec4 color;
void main() { color = texelFetch(source, ivec2(gl_FragCoord.xy), 0); }
"""
