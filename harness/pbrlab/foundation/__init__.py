"""The foundation layer: what every other layer stands on and that knows nothing of shading.

Errors and the locations they name (``errors``, ``locations``), console output and progress
(``console``, ``progress``), outputs written as transactions and never over an input
(``outputs``, ``golden_names``), file identity and the disk cache (``file_identity``,
``disk_cache``), checked JSON input (``json_input``), lossless images (``images``), and the
package's layer map itself (``layers``). Imports nothing from the package above it.
"""
