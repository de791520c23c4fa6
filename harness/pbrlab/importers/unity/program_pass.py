"""Compile a vertex/fragment pass (``model.VertexFragmentPass``) into a GL program.

    program = build_pass_program(ctx, vf, "hlsl", defines, blended=False)

HLSL: each stage's generated text (``generate_pass``) through glslang and spirv-cross, as the
surface path's HLSL vertex stage. GLSL: the same entry points around the ``port-unity`` port
of the program, included as an in-memory file named after the ``.shader`` (errors read
``X.shader:LINE`` on both paths). Programs live in the context's scene-program cache, keyed
on every file they read; binding is ``program.bind``'s, as for a surface program.
"""

from __future__ import annotations

import atexit
import shutil
import tempfile
from pathlib import Path

from ...gpu import hlsl, programs, shaders
from ...foundation.errors import PbrlabError
from ...foundation.file_identity import include_closure
from . import finite_texture_coordinates, generate, generate_pass, geometry_stage, glslprogram, tessellation_stage
from .compared_textures import texture_reads
from .shadow_sampler_globals import same_shadow_globals, typed_shadow_globals
from .texture_gather import crossed_glsl, with_gather_extensions
from . import model as M
from . import unprovided
from .program import (TEMPLATES, hlsl_includes, hlsl_program, indexed, ported_sources, program_include, rename_vertex_globals)
from .source_text import (CGINC, INCLUDE, PACKAGE_STAND_INS, blank_comments, included_text,
                          own_package_root, project_root)

_STAGES = {"vertex": "vert", "fragment": "frag"}


_PACKAGE_LINKS: dict = {}


# The include files a package's own paths may name (copied for glslang: package_links).
_INCLUDE_SUFFIXES = {".hlsl", ".cginc", ".hlslinc", ".glslinc", ".inc", ".compute"}


def package_links(package: str, root: Path) -> Path:
    """A folder (one per process and package, removed at exit) holding ``Packages/<package>``:
    a copy of the include files under the package's folder ``root``, through which glslang,
    which resolves an #include by folders alone, finds the package's own
    ``Packages/<package>/...`` paths (a copy, not a link: the include closure reads no link
    that leads out of its folder)."""
    key = (package, Path(root).resolve())
    if key not in _PACKAGE_LINKS:
        folder = Path(tempfile.mkdtemp(prefix="pbrlab-unity-package-"))
        atexit.register(shutil.rmtree, folder, True)
        for path in key[1].rglob("*"):
            if path.suffix.lower() in _INCLUDE_SUFFIXES and path.is_file() and not path.is_symlink():
                copy = folder / "Packages" / package / path.relative_to(key[1])
                copy.parent.mkdir(parents=True, exist_ok=True)
                shutil.copyfile(path, copy)
        _PACKAGE_LINKS[key] = folder
    return _PACKAGE_LINKS[key]


def with_package_copies(replaced: dict) -> dict:
    """``replaced`` ({path: text} compiled in place of a shader's own includes: hlsl_includes),
    with the same text for each package copy of such a file (package_links): glslang reaches a
    file the program names by ``Packages/<package>/...`` through the copy."""
    out = dict(replaced)
    for (package, root), folder in _PACKAGE_LINKS.items():
        for path, text in replaced.items():
            resolved = Path(path).resolve()
            if resolved.is_relative_to(root):
                out[folder / "Packages" / package / resolved.relative_to(root)] = text
    return out


def _stage_text(vf, language: str, stage: str, defines: dict, blended: bool, program_text: str,
                display: str, before_program: str = "") -> str:
    where = f"{vf.path}:{vf.program_line}"
    head = generate.prelude(language, defines, vertex_stage=stage == "vertex")
    if language == "hlsl":
        line = hlsl.line_directive(vf.program_line, display)
    else:
        line = "#line 1"
    if stage == "vertex":
        entry = generate_pass.vertex_entry(vf, language, where)
    else:
        entry = generate_pass.fragment_entry(vf, language, where, blended)
    return "\n".join(head) + "\n" + before_program + line + "\n" + program_text + "\n" + entry


def build_pass_program(ctx, vf: M.VertexFragmentPass, language: str, defines: dict, blended: bool):
    key = ("unity-pass", str(vf.path), vf.program, vf.program_line, vf.vertex, vf.fragment, language,
           blended, tuple(sorted(defines.items())))

    def build():
        # the Unity project's roots its project-path includes resolve from (Assets/..., Packages/...)
        names = [m.group(1) for m in INCLUDE.finditer(blank_comments(vf.program + "\n" + included_text(vf.program, vf.path.parent)))]
        roots = {project_root(n, vf.path.parent) for n in names}
        # a package's own paths (Packages/<it>/...) from a folder that links Packages/<it> to it
        roots |= {package_links(*own) for own in (own_package_root(n, vf.path.parent) for n in names) if own}
        # (pbrlab's stand-ins before the project's roots: a project's embedded copy of Unity's
        # render-pipeline packages is read as the stand-ins, as resolve_included reads it for the port)
        # (the stand-ins' parent last: the name a project's copy is replaced by, vendored_library.own_include)
        dirs = [TEMPLATES, vf.path.parent, CGINC, PACKAGE_STAND_INS, *sorted(r for r in roots if r is not None),
                PACKAGE_STAND_INS.parent]
        if vf.language == glslprogram.LANGUAGE:  # a GLSLPROGRAM: its GLSL as written, in either language
            program, paths = glslprogram.build_glsl_program(ctx, vf, defines, blended, dirs)
            return indexed(program, vf.path), paths
        stages, paths, crossed = {}, [vf.path], {}
        tessellated = vf.tessellation is not None  # #pragma hull / domain: tessellation_stage.py
        geometry = vf.geometry is not None or tessellated  # a #pragma geometry: geometry_stage.py
        behind = geometry_stage.fragment_pass if vf.geometry is not None else tessellation_stage.fragment_pass
        for stage in ("vertex", "fragment"):
            display = f"{vf.path.name} (generated {language} {stage} stage)"
            # behind a geometry (domain) stage the fragment reads its output struct's varyings
            stage_vf = behind(vf) if geometry and stage == "fragment" else vf
            if language == "hlsl":
                text = _stage_text(stage_vf, "hlsl", stage, defines, blended, hlsl_program(vf), str(vf.path))
                glsl = crossed_glsl(hlsl.compile_spirv(text, display, dirs, stage=_STAGES[stage],  # (texture_gather.py)
                                                       replaced=with_package_copies(hlsl_includes(vf))))
                glsl = finite_texture_coordinates.applied(glsl)  # lookups at NaN / inf: as Direct3D's
                if stage == "vertex":
                    glsl = rename_vertex_globals(glsl)
                elif geometry:
                    glsl = geometry_stage.fragment_inputs_renamed(glsl)
                crossed[stage] = (glsl, [f"{display} (GLSL from spirv-cross)"])
                paths += include_closure(text, [*dirs, hlsl.HLSL_ROOT])
            else:
                include, virtual = program_include(vf)
                text = _stage_text(stage_vf, "glsl", stage, defines, blended, include, vf.path.name,
                                   geometry_stage.glsl_stage_macros(vf, False))  # (also for an unused geom)
                if geometry and stage == "fragment":
                    text = geometry_stage.fragment_inputs_renamed(text)
                # (textureGather, Core RP's gathers: its GLSL 3.30 extensions, texture_gather.py)
                stages[stage] = with_gather_extensions(
                    shaders.expand(text, display, include_dirs=dirs, virtual=virtual))
                paths += stages[stage].paths + ported_sources(virtual)
        if crossed:  # one type per comparison-sampled global in both stages (shadow_sampler_globals.py),
            # by the program's reads of each texture, as the GLSL port's (compared_textures.py)
            reads = texture_reads(vf.program + "\n" + included_text(vf.program, vf.path.parent))
            retyped = same_shadow_globals({stage: typed_shadow_globals(glsl, reads) for stage, (glsl, _) in crossed.items()})
            stages.update({stage: shaders.Source(retyped[stage], names) for stage, (_, names) in crossed.items()})
        if geometry:
            include, virtual = program_include(vf) if language == "glsl" else (hlsl_program(vf), None)
            shown = str(vf.path) if language == "hlsl" else vf.path.name
            read = []
            if tessellated:
                stages["tess_control"], stages["tess_evaluation"], read = tessellation_stage.build_tessellation_stages(
                    vf, language, defines, dirs, include, shown, virtual)
            if vf.geometry is not None:  # (behind tessellation stages it is given the domain's vertices)
                stages["geometry"], more = geometry_stage.build_geometry_stage(
                    tessellation_stage.fragment_pass(vf) if tessellated else vf, language, defines, dirs, include,
                    shown, virtual)
                read += more
            paths += read + (ported_sources(virtual) if virtual else [])
            program = geometry_stage.link_stages(ctx, stages)
        else:
            program = shaders.build_program(ctx, stages["vertex"], stages["fragment"])
        program = indexed(program, vf.path)
        if tessellated:  # drawn as patches (renderer._draw_mesh)
            program.extra["patch_vertices"] = tessellation_stage.PATCH_VERTICES
        return program, paths

    try:
        return programs.program_cache(ctx).get(key, build)
    except PbrlabError as exc:  # a Unity name pbrlab leaves out on purpose: say which feature
        unprovided.raise_named(exc, vf.path)
