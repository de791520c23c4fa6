"""The golden store's names that the pytest plugin needs when it registers its options,
importable without numpy, OpenImageIO or a GL library: the default folders and the names of
the tolerance profiles (``compare.TOLERANCE_PROFILES`` holds the profiles themselves; a test
checks both name the same ones)."""

DEFAULT_ROOT = "goldens"
DEFAULT_OUTPUT_DIR = "test-output"
TOLERANCE_PROFILE_NAMES = ("llvmpipe", "gpu")
