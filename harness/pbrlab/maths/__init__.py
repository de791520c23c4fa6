"""Maths and the float64 references: the library's formulas in numpy (``reference``), the exact
sRGB encode (``srgb8``), mip chains (``mipmaps``), the camera's projection (``camera``) and
metered exposure (``exposure``). No GL here: everything runs on the CPU in float64 (or the
stated precision)."""
