// pbrlab stand-in for Unity's TextCoreProperties.cginc (TextCore-SDF, TextCore-SDF-SSD and user
// TextCore shaders).
//
// Provides: the uniforms of TextCore's signed-distance-field font materials, by the names of
//   their Properties: the face (_FaceColor, _FaceDilate), the outline (_OutlineColor,
//   _OutlineWidth, _OutlineSoftness), the underlay (_UnderlayColor, _UnderlayOffsetX,
//   _UnderlayOffsetY, _UnderlayDilate, _UnderlaySoftness), the weights (_WeightNormal,
//   _WeightBold), _ShaderFlags, the scale ratios (_ScaleRatioA, _ScaleRatioB, _ScaleRatioC), the
//   font atlas (_MainTex, _TextureWidth, _TextureHeight, _GradientScale), _ScaleX, _ScaleY,
//   _Sharpness, _VertexOffsetX, _VertexOffsetY.
// Unity's file: the material properties TextCore's SDF shaders declare (their Properties blocks
//   name each one) as the globals its programs read; written here anew from those blocks.
// Differences: Unity's file declares further properties of TextCore's other shaders (glow,
//   bevel, masking); a shader that reads one of those is refused by the compiler's naming of it.
// Cg text in the plain subset harness/pbrlab/importers/unity/port.py ports to GLSL.
#ifndef PBRLAB_TEXT_CORE_PROPERTIES_CGINC
#define PBRLAB_TEXT_CORE_PROPERTIES_CGINC

uniform fixed4 _FaceColor;
uniform float _FaceDilate;

uniform fixed4 _OutlineColor;
uniform float _OutlineWidth;
uniform float _OutlineSoftness;

uniform fixed4 _UnderlayColor;
uniform float _UnderlayOffsetX;
uniform float _UnderlayOffsetY;
uniform float _UnderlayDilate;
uniform float _UnderlaySoftness;

uniform float _WeightNormal;
uniform float _WeightBold;
uniform float _ShaderFlags;
uniform float _ScaleRatioA;
uniform float _ScaleRatioB;
uniform float _ScaleRatioC;

uniform sampler2D _MainTex;
uniform float _TextureWidth;
uniform float _TextureHeight;
uniform float _GradientScale;
uniform float _ScaleX;
uniform float _ScaleY;
uniform float _Sharpness;
uniform float _VertexOffsetX;
uniform float _VertexOffsetY;

#endif
