"""MkDocs hook of the pbrlab site (mkdocs.yml, ``hooks:``): the goldens the pages show.

MkDocs serves only what lies under ``docs/``; the pictures of the front pages are goldens
(``goldens/NAME.png``, the renders the tests compare against). Rather than commit a second
copy of each, the build takes the named ones from ``goldens/`` itself and serves them at
``goldens/NAME.png`` in the site, so a page links ``goldens/NAME.png`` (``../goldens/...`` from
a page one folder down) and a link to a golden not named here fails the --strict build
like any broken link. The sdist carries both folders (MANIFEST.in), so it builds too.
"""

from __future__ import annotations

from pathlib import Path

from mkdocs.exceptions import PluginError
from mkdocs.structure.files import File

# The goldens some page shows, and where.
PICTURES = {
    "lit_scene_high": "index.md (the lit example), unity.md (its Unity-style surface shader)",
    "chart_metallic": "getting-started.md (a material chart of `make demo`)",
    "gltf_features_environment": "gltf.md (a glTF test asset under a constant sky)",
}


def on_files(files, config):
    root = Path(config["config_file_path"]).parent
    for name in PICTURES:
        path = root / "goldens" / f"{name}.png"
        if not path.is_file():
            raise PluginError(f"scripts/mkdocs_goldens.py: PICTURES names {path}, which does not exist")
        files.append(File(f"goldens/{name}.png", src_dir=str(root), dest_dir=config["site_dir"],
                          use_directory_urls=config["use_directory_urls"]))
    return files
