"""AMD GPU instruction-set costs without an AMD GPU: Mesa's RADV compiles the library's
programs for a forced GPU family on a "null" Vulkan device, and reports ACO's statistics
(instructions, VGPRs, SGPRs, code size, latency and inverse-throughput estimates) and the
disassembly. See :mod:`pbrlab.gpu.isa.compile` for the entry point."""
