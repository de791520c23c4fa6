"""MkDocs hooks of the pbrlab site (mkdocs.yml, ``hooks:``): pages generated from the code.

``library-files.md``: every GLSL file of the library (glsl/pbr/ and glsl/unity_compat/), by
folder, with its one-line summary and its header's Provides / Include / Config macros read
fields exactly as the file states them. The files are the truth; this page cannot drift from
them, since it is written from them at every build.

``scenes.md``: the scene-file reference's tables, rendered from the JSON Schema
(``pbrlab.scene.schema``, itself written from the parser's field tables) where the page
says ``<!-- scene-schema -->``.
"""

from __future__ import annotations

import json
import re
import sys
from pathlib import Path

from mkdocs.structure.files import File

PAGE = "library-files.md"
FIELD = re.compile(r"^// (Provides|Include|Config macros read):")
CONTINUATION = re.compile(r"^//\s{2,}\S")  # a field's next line: indented under it


def header_fields(text: str) -> tuple[str, list[str]]:
    """(the summary of the first line, the lines of the three header fields, verbatim)."""
    lines = text.splitlines()
    first = lines[0].removeprefix("//").strip()
    summary = [first.split(": ", 1)[1] if ": " in first else first]
    for line in lines[1:]:  # the summary may wrap, up to the header's empty comment line
        if line.strip() == "//" or FIELD.match(line) or not line.startswith("//"):
            break
        summary.append(line.removeprefix("//").strip())
    fields, inside = [], False
    for line in lines[1:]:
        if FIELD.match(line):
            inside = True
        elif not (inside and CONTINUATION.match(line)):
            inside = False
        if inside:
            fields.append(line)
    return " ".join(summary), fields


def library_files_page(glsl_root: Path) -> str:
    out = ["# Library files",
           "",
           "Every file of the GLSL library with the header it opens with (generated from the files at",
           "each build by `scripts/mkdocs_hooks.py`). The HLSL twins in `hlsl_ports/` have the same",
           "paths with `.hlsl` ([HLSL and engines](hlsl.md)); the naming rule, the variant selectors and",
           "the measured error of each function are on [The shader library](library.md).",
           ""]
    files = sorted(glsl_root.rglob("*.glsl"), key=lambda p: (p.parent.as_posix(), p.name))
    folder = None
    for path in files:
        relative = path.relative_to(glsl_root)
        if relative.parent != folder:
            folder = relative.parent
            out += [f"## `{folder.as_posix()}/`", ""]
        summary, fields = header_fields(path.read_text(encoding="utf-8"))
        out += [f"### `{relative.as_posix()}`", "", summary, "", "```glsl", *fields, "```", ""]
    return "\n".join(out)


def on_files(files, config):
    root = Path(config["config_file_path"]).parent
    files.append(File.generated(config, PAGE, content=library_files_page(root / "glsl")))
    return files


# --- The scene-file reference (docs/scenes.md): tables rendered from the JSON Schema -------

SCHEMA_MARKER = "<!-- scene-schema -->"
# The schema's $defs in the order the page shows them, with their headings.
SCHEMA_SECTIONS = {"camera": "`camera`", "light": "`lights[]`", "environment": "`environment`",
                   "material": "`materials{}`", "sphere_object": "`objects[]`: a sphere",
                   "sphere": "`sphere`", "mesh_object": "`objects[]`: a mesh", "primitive": "`mesh`: a primitive",
                   "transform": "`transform`", "gltf_object": "`objects[]`: a glTF scene", "render": "`render`"}
FLOAT32_LIMIT = 3.4e38  # bounds at float32's largest value are json_input's, not a field's own


def _anchor(name: str) -> str:
    return f"#schema-{name.replace('_', '-')}"


def _number(schema: dict) -> str:
    lo = schema.get("exclusiveMinimum", schema.get("minimum"))
    hi = schema.get("maximum")
    lo = None if lo is None or abs(lo) > FLOAT32_LIMIT else lo
    hi = None if hi is None or abs(hi) > FLOAT32_LIMIT else hi
    kind = schema.get("type", "number")
    if lo is None and hi is None:
        return kind
    if hi is None:
        return f"{kind} {'>' if 'exclusiveMinimum' in schema else '≥'} {lo:g}"
    opening = "(" if "exclusiveMinimum" in schema else "["
    return f"{kind} in {opening}{lo:g}, {hi:g}]" if lo is not None else f"{kind} ≤ {hi:g}"


def schema_type(schema: dict) -> str:
    """A field's schema as a short phrase: `3 numbers in [0, 1]`, `one of a, b`, ..."""
    if schema is False:
        return "refused"
    if "$ref" in schema:
        name = schema["$ref"].rsplit("/", 1)[1]
        return f"[{name}]({_anchor(name)})"
    if "enum" in schema:
        return "one of " + ", ".join(f"`{json.dumps(v).strip(chr(34))}`" for v in schema["enum"])
    if "const" in schema:
        return f"`{schema['const']}`"
    if "oneOf" in schema:
        return " or ".join(schema_type(s) for s in schema["oneOf"])
    kind = schema.get("type")
    if kind == "array":
        n = schema.get("minItems")
        count = f"{n} " if n is not None and n == schema.get("maxItems") else ""
        items = schema_type(schema.get("items", {}))
        plural = items.replace("number", "numbers", 1).replace("integer", "integers", 1)
        extra = ", not all 0" if "not" in schema else ""
        return f"{count}{plural if count != '1 ' else items}{extra}" if count else f"list of {items}"
    if kind in ("number", "integer"):
        return _number(schema)
    if kind == "string":
        return "file path" if schema.get("minLength") else "string"
    if kind == "object":
        return "object"
    return kind or "any"


def _condition(schema: dict) -> str:
    if "not" in schema and schema["not"].get("required"):
        return f"without `{'`, `'.join(schema['not']['required'])}`"
    if schema.get("required") and not schema.get("properties"):
        return f"with `{'`, `'.join(schema['required'])}`"
    (key, value), = schema["properties"].items()
    return f"`{key}` is `{value['const']}`"


def _consequence(schema: dict) -> str:
    parts = []
    if schema.get("required"):
        parts.append(f"requires `{'`, `'.join(schema['required'])}`")
    refused = [k for k, v in schema.get("properties", {}).items() if v is False]
    if refused:
        parts.append(f"refuses `{'`, `'.join(refused)}`")
    for key, value in schema.get("properties", {}).items():
        if value is not False and "propertyNames" in value:
            parts.append(f"`{key}` takes the slots {', '.join(f'`{v}`' for v in value['propertyNames']['enum'])}")
        elif value is not False and "exclusiveMinimum" in value:
            parts.append(f"`{key}` > {value['exclusiveMinimum']:g}")
    return "; ".join(parts) or "no constraint"


def schema_rules(schema: dict) -> list[str]:
    """The object's rules across fields, as sentences."""
    rules = []
    for rule in schema.get("allOf", []):
        rules.append(f"{_condition(rule['if'])}: {_consequence(rule['then'])}"
                     + (f"; otherwise {_consequence(rule['else'])}" if "else" in rule else ""))
    for key, rule in schema.get("dependentSchemas", {}).items():
        rules.append(f"with `{key}`: {_consequence(rule)}")
    for key, needed in schema.get("dependentRequired", {}).items():
        rules.append(f"with `{key}`: requires `{'`, `'.join(needed)}`")
    for alternative in schema.get("oneOf", []):
        if list(alternative) == ["required"]:
            rules.append(f"exactly one of {', '.join(f'`{k}`' for a in schema['oneOf'] for k in a['required'])}")
            break
    return rules


def _cell(text: str) -> str:
    return text.replace("|", "\\|").replace("\n", " ")


def scene_reference(schema: dict, parser_only_rules) -> str:
    """The scene format's tables, one per object of the schema, then the parser's own checks."""
    out = ["The tables below are rendered from the JSON Schema at each build (`pbrlab schema` prints",
           "it; `scripts/mkdocs_hooks.py` writes these tables), which is written from the parser's own",
           "field tables (`pbrlab/scene/fields.py`).", ""]
    out += ["### The top level {#schema-top-level}", "", schema["description"], "",
            "| field | type | meaning |", "|---|---|---|"]
    for key, field in schema["properties"].items():
        kind = schema_type(field) if "$ref" in field or field.get("type") != "array" else \
            f"list of {schema_type(field['items'])}"
        if field.get("type") == "object" and "additionalProperties" in field:
            kind = f"name → {schema_type(field['additionalProperties'])}"
        if "oneOf" in field.get("items", {}):
            kind = "list of " + " or ".join(schema_type(s) for s in field["items"]["oneOf"])
        out.append(f"| `{key}` | {_cell(kind)} | {_cell(field.get('description', ''))} |")
    out += ["", f"Required: `{'`, `'.join(schema['required'])}`; and `camera` unless an object is a glTF scene.", ""]
    defs = schema["$defs"]
    for name, heading in SCHEMA_SECTIONS.items():
        node = defs[name]
        out += [f"### {heading} {{#{_anchor(name)[1:]}}}", "", node.get("description", ""), ""]
        variants = node.get("oneOf", [])
        objects = [v for v in variants if v.get("type") == "object" and "properties" in v]
        if name == "primitive":
            out += ["| primitive | parameters (default) |", "|---|---|"]
            for v in objects:
                params = [f"`{k}` {schema_type(p)} ({p['default']})" for k, p in v["properties"].items()
                          if k != "primitive"]
                out.append(f"| `{v['properties']['primitive']['const']}` | {', '.join(params)} |")
            out.append("")
            continue
        if objects:  # environment: null or an object
            out += [f"`null`, or an object:", ""]
            node = objects[0]
        required = set(node.get("required", []))
        out += ["| field | type | default | meaning |", "|---|---|---|---|"]
        for key, field in node["properties"].items():
            default = json.dumps(field["default"]) if "default" in field else ("required" if key in required else "")
            out.append(f"| `{key}` | {_cell(schema_type(field))} | {_cell(default)} | "
                       f"{_cell(field.get('description', ''))} |")
        out.append("")
        rules = schema_rules(node)
        if rules:
            out += ["Rules across fields:", "", *[f"- {r}" for r in rules], ""]
    out += ["### What the parser checks beyond the schema", "",
            "`pbrlab render` (the parser, `pbrlab.scene.model`) refuses these too, naming the field:", "",
            *[f"- {r}" for r in parser_only_rules], ""]
    return "\n".join(out)


def on_page_markdown(markdown, page, config, files):
    if SCHEMA_MARKER not in markdown:
        return markdown
    root = Path(config["config_file_path"]).parent
    if (root / "harness" / "pbrlab").is_dir():  # this checkout's package, not an installed one
        sys.path.insert(0, str(root / "harness"))
    from pbrlab.scene.schema import PARSER_ONLY_RULES, scene_schema

    return markdown.replace(SCHEMA_MARKER, scene_reference(scene_schema(), PARSER_ONLY_RULES))
