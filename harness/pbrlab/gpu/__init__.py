"""The GPU layer: the GL context (``gl``, ``gl_limits``), shader sources and includes
(``shaders``, ``source_cache``, ``hlsl``, ``port_hlsl``), programs and their bindings
(``programs``, ``surface_bindings``), render targets and readback (``targets``), the GLSL
evaluator (``evaluator``), the image-based-light tables (``ibl``, ``sheen_table``,
``engine_tables``, ``data/``) and the AMD instruction counter (``isa``). It knows shaders and
textures, never a scene."""
