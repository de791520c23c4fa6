"""External images in a ``GLSLPROGRAM`` (OpenGL ES's ``GL_OES_EGL_image_external`` and
``GL_OES_EGL_image_external_essl3``): a ``samplerExternalOES`` is the sampler an Android app binds
a camera or video frame to (an EGLImage). Desktop OpenGL has no such sampler; the image the app
would bind is, here, the 2D texture the material gives the property (or the default texture of
an implicit one), so the snippet's external sampler is spelled ``sampler2D``:

    code = spelled_for_desktop(code)     # glslprogram._spell, on the snippet's code

What differs from a device, and is written in docs/unity.md ("External images"):

- The driver converts an external image from the camera's or decoder's YUV to RGB as it samples
  (OES_EGL_image_external: the sampled value is RGB, converted in a way the implementation
  chooses); pbrlab does no conversion: the supplied texture holds that RGB.
  Unity's video path (VideoDecodeAndroid.shader) reads the external texel as RGBA already, so
  nothing of the shader's own arithmetic is lost.
- The extension allows no mipmaps and only CLAMP_TO_EDGE wrapping on an external texture
  (its texture-parameter rules); the 2D texture is sampled with the material's usual sampler state, which
  reads the same texels for coordinates in [0, 1] seen at no more than one texel per pixel.

Sources: Khronos, OES_EGL_image_external (revision 21) and OES_EGL_image_external_essl3
(revision 6): ``samplerExternalOES`` read by ``texture2D`` (ESSL 1.00) or ``texture``
(ESSL 3.00); Unity's ``textureExternal`` (UnityCG.glslinc) is the reading function of the
snippet's language (pbrlab's stand-in defines it as ``texture``).
"""

from __future__ import annotations

import re

# ``#extension GL_OES_EGL_image_external : require`` (or the _essl3 one): desktop GL would fail
# a `require` of an extension it does not have; the line becomes a comment.
_EXTENSION = re.compile(r"^([ \t]*#[ \t]*extension[ \t]+GL_OES_EGL_image_external(?:_essl3)?\b[^\n]*)", re.M)
_SAMPLER = re.compile(r"\bsamplerExternalOES\b")


def uses_external_images(code: str) -> bool:
    """Whether the snippet's code (comments blanked) declares or enables an external image."""
    return bool(_SAMPLER.search(code) or _EXTENSION.search(code))


def spelled_for_desktop(code: str) -> str:
    """``code`` with its external-image extension line commented out and each
    ``samplerExternalOES`` a ``sampler2D`` (module docstring), line for line."""
    code = _EXTENSION.sub(r"// \1", code)
    return _SAMPLER.sub("sampler2D", code)
