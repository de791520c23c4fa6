import importlib.util
from pathlib import Path

import pytest

from site_build import ROOT, mkdocs_build

# The site's build needs these (requirements.txt); a missing one is a set-up problem, named.
SITE_PACKAGES = {"mkdocs": "mkdocs", "material": "mkdocs-material", "mkdocstrings": "mkdocstrings",
                 "mkdocstrings_handlers.python": "mkdocstrings-python"}


def _importable(module: str) -> bool:
    try:
        return importlib.util.find_spec(module) is not None
    except ModuleNotFoundError:  # its parent package is missing
        return False


@pytest.fixture(scope="session")
def site_tools() -> None:
    """Fails, naming what to run, when a package the build needs is not installed."""
    missing = [package for module, package in SITE_PACKAGES.items() if not _importable(module)]
    assert not missing, f"not installed: {', '.join(missing)} (bash scripts/setup.sh installs them)"


@pytest.fixture(scope="session")
def built_site(site_tools, tmp_path_factory) -> Path:
    """The documentation site, built once with --strict from the checkout."""
    site = tmp_path_factory.mktemp("docs") / "site"
    result = mkdocs_build(ROOT / "mkdocs.yml", site)
    assert result.returncode == 0, result.stdout + result.stderr
    return site
