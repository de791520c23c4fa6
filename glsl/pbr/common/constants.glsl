// pbr/common/constants.glsl: mathematical constants of the pbrlab shading library.
//
// Provides: PBR_PI, PBR_INV_PI, PBR_TWO_PI, PBR_HALF_PI.
// Include:  "pbr/common/constants.glsl" (path relative to glsl/)
// Config macros read: none.
//
// Values are written to 9 significant digits (more than float32 resolves); the float64
// twins live in harness/pbrlab/maths/reference/constants.py and tests/library/test_glsl_layout.py
// checks that the GPU sees the float32 rounding of the same numbers.
// SPDX-License-Identifier: MIT. Part of pbrlab (https://spdx.org/licenses/MIT); full text in its LICENSE file.
#ifndef PBR_COMMON_CONSTANTS_GLSL
#define PBR_COMMON_CONSTANTS_GLSL

#define PBR_PI      3.14159265358979
#define PBR_INV_PI  0.318309886183791
#define PBR_TWO_PI  6.28318530717959
#define PBR_HALF_PI 1.57079632679490

#endif // PBR_COMMON_CONSTANTS_GLSL
