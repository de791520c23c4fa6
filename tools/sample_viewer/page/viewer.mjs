// The page render.mjs drives: one glTF render with the Khronos glTF Sample Renderer,
// read back as linear float radiance (before any tonemap or sRGB encode).
//
// Two hooks on the WebGL2 context, both outside the viewer's code:
//  * the default framebuffer (null) is redirected to an RGBA32F framebuffer of the
//    render's size, so what the viewer draws "to the canvas" is kept in float32, without
//    multisampling or, with spec.msaa = N, multisampled N times and resolved by a blit;
//  * every shader with a LINEAR_OUTPUT branch (the viewer's pbr and environment shaders)
//    is compiled with LINEAR_OUTPUT defined: the viewer's own switch, used for its
//    transmission pass, which writes the shaded colour without u_Exposure, tonemap and its
//    pow(1/2.2) encode.
// With an environment, its background (renderEnvironmentMap) is drawn into the viewer's
// transmission copy, as the viewer draws it when it shows the environment, so that a
// transmissive surface sees the sky where nothing opaque is behind it; it is kept out of the
// final image (backgroundInCopyOnly), whose clear alpha 0 then still marks coverage and whose
// blended surfaces lie over transparent black, as pbrlab's do.
import { GltfState, GltfView } from "/viewer/gltf-viewer.module.js";

function floatRenderbuffer(gl, samples, format, width, height) {
  const buffer = gl.createRenderbuffer();
  gl.bindRenderbuffer(gl.RENDERBUFFER, buffer);
  if (samples > 0) gl.renderbufferStorageMultisample(gl.RENDERBUFFER, samples, format, width, height);
  else gl.renderbufferStorage(gl.RENDERBUFFER, format, width, height);
  return buffer;
}

function framebufferOf(gl, color, depth) {
  const fbo = gl.createFramebuffer();
  gl.bindFramebuffer(gl.FRAMEBUFFER, fbo);
  gl.framebufferRenderbuffer(gl.FRAMEBUFFER, gl.COLOR_ATTACHMENT0, gl.RENDERBUFFER, color);
  if (depth) gl.framebufferRenderbuffer(gl.FRAMEBUFFER, gl.DEPTH_ATTACHMENT, gl.RENDERBUFFER, depth);
  const status = gl.checkFramebufferStatus(gl.FRAMEBUFFER);
  if (status !== gl.FRAMEBUFFER_COMPLETE) throw new Error(`float framebuffer incomplete (0x${status.toString(16)})`);
  return fbo;
}

// samples > 0: the redirected framebuffer is multisampled (renderbufferStorageMultisample,
// RGBA32F and DEPTH_COMPONENT24) and resolve() blits it into a single-sample RGBA32F one,
// as a multisampled canvas is resolved. Returns {target: what the default framebuffer
// stands for, resolve: () => the framebuffer to read}.
function linearTarget(gl, width, height, samples) {
  if (!gl.getExtension("EXT_color_buffer_float")) throw new Error("EXT_color_buffer_float is missing");
  gl.getExtension("EXT_float_blend");  // blending into RGBA32F (BLEND materials)
  if (samples > 0) {
    const offered = Array.from(gl.getInternalformatParameter(gl.RENDERBUFFER, gl.RGBA32F, gl.SAMPLES) || []);
    if (!offered.includes(samples))
      throw new Error(`msaa ${samples}: this WebGL implementation offers RGBA32F renderbuffers with ${JSON.stringify(offered)} samples`);
  }
  const fbo = framebufferOf(gl, floatRenderbuffer(gl, samples, gl.RGBA32F, width, height),
                            floatRenderbuffer(gl, samples, gl.DEPTH_COMPONENT24, width, height));
  const resolved = samples > 0 ? framebufferOf(gl, floatRenderbuffer(gl, 0, gl.RGBA32F, width, height), null) : fbo;
  const bind = gl.bindFramebuffer.bind(gl);
  gl.bindFramebuffer = (target, framebuffer) => bind(target, framebuffer === null ? fbo : framebuffer);
  const source = gl.shaderSource.bind(gl);
  gl.shaderSource = (shader, text) => source(shader, text.includes("LINEAR_OUTPUT")
    ? text.replace("#version 300 es\n", "#version 300 es\n#define LINEAR_OUTPUT 1\n") : text);
  const resolve = () => {
    if (resolved !== fbo) {
      bind(gl.READ_FRAMEBUFFER, fbo);
      bind(gl.DRAW_FRAMEBUFFER, resolved);
      gl.disable(gl.SCISSOR_TEST);
      gl.blitFramebuffer(0, 0, width, height, 0, 0, width, height, gl.COLOR_BUFFER_BIT, gl.NEAREST);
    }
    bind(gl.FRAMEBUFFER, resolved);
    return resolved;
  };
  return { target: fbo, resolve };
}

// The viewer's EnvironmentRenderer (created by the renderer's first init) draws the
// background before the transmission copy's scene and before the final image's; only the
// first draw is let through: the final image is the float target behind the default
// framebuffer. Returns a check that the hook was installed (a newer viewer that renames
// renderer.environmentRenderer fails loudly instead of drawing the background everywhere).
function backgroundInCopyOnly(gl, renderer, finalTarget) {
  if (!renderer || "environmentRenderer" in renderer) throw new Error("gltf-viewer: renderer.environmentRenderer not as expected");
  let environmentRenderer;
  Object.defineProperty(renderer, "environmentRenderer", {
    get: () => environmentRenderer,
    set: (value) => {
      const draw = value.drawEnvironmentMap.bind(value);
      value.drawEnvironmentMap = (...args) => {
        if (gl.getParameter(gl.DRAW_FRAMEBUFFER_BINDING) !== finalTarget) draw(...args);
      };
      environmentRenderer = value;
    },
  });
  return () => {
    if (environmentRenderer === undefined) throw new Error("gltf-viewer: no environmentRenderer after the frame");
  };
}

function toBase64(bytes) {
  let text = "";
  for (let i = 0; i < bytes.length; i += 0x8000) text += String.fromCharCode(...bytes.subarray(i, i + 0x8000));
  return btoa(text);
}

// spec: {gltf: url, environment: url | null, environmentIntensity, environmentRotationDeg,
//        size: [w, h], msaa: samples (0: none), camera: {cameraToWorld: 16 numbers column-major, yfovRad, znear, zfar}
//        | {index: glTF camera index}}
window.renderGltf = async (spec) => {
  const [width, height] = spec.size;
  const canvas = document.createElement("canvas");
  canvas.width = width;
  canvas.height = height;
  const gl = canvas.getContext("webgl2", { antialias: false, alpha: true, premultipliedAlpha: false });
  if (!gl) throw new Error("no WebGL2 context (run chromium with --use-angle=swiftshader --enable-unsafe-swiftshader)");
  const { target: fbo, resolve } = linearTarget(gl, width, height, spec.msaa ?? 0);
  const view = new GltfView(gl);
  const checkBackgroundHook = backgroundInCopyOnly(gl, view.renderer, fbo);
  const state = view.createState();
  // No KTX2 (libktx) and no Draco decoder: pbrlab's importer reads neither, so an asset
  // that needs one is outside this comparison. The viewer probes the global LIBKTX and
  // takes a Draco module factory; this one reports ready with no decoder.
  window.LIBKTX = undefined;
  const noDraco = (module) => module.onModuleLoaded({});
  const loader = view.createResourceLoader(noDraco, undefined, "/viewer/libs/");
  const t0 = performance.now();
  state.gltf = await loader.loadGltf(spec.gltf);
  const t1 = performance.now();
  state.sceneIndex = state.gltf.scene ?? 0;
  const p = state.renderingParameters;
  p.clearColor = [0, 0, 0, 0];  // alpha 0 outside the model: the coverage mask
  p.renderEnvironmentMap = Boolean(spec.environment);  // into the transmission copy only
  p.blurEnvironmentMap = false;
  p.toneMap = GltfState.ToneMaps.NONE;  // not applied under LINEAR_OUTPUT; named for clarity
  p.exposure = 1.0;
  p.usePunctual = true;  // the file's KHR_lights_punctual only:
  p.useDirectionalLightsWithDisabledIBL = false;  // no generated key and fill lights
  // The renderer binds an environment's textures even with IBL off: without one, a black
  // one. lut_sheen_E_unused.png (1x1 white) stands in for the sheen albedo table that the
  // npm package does not ship; only KHR_materials_sheen reads it.
  state.environment = await loader.loadEnvironment(spec.environment || "/page/black.hdr",
    { lut_sheen_E_file: "/page/lut_sheen_E_unused.png" });
  const t2 = performance.now();
  if (spec.environment) {
    p.useIBL = true;
    p.iblIntensity = spec.environmentIntensity ?? 1.0;
    p.environmentRotation = spec.environmentRotationDeg ?? 90.0;
  } else {
    p.useIBL = false;
  }
  if (spec.camera.index !== undefined) {
    state.cameraIndex = spec.camera.index;
  } else {
    const camera = state.userCamera;
    camera.transform = new Float32Array(spec.camera.cameraToWorld);
    camera.perspective.yfov = spec.camera.yfovRad;
    camera.perspective.znear = spec.camera.znear;
    camera.perspective.zfar = spec.camera.zfar;
  }
  view.renderFrame(state, width, height);
  checkBackgroundHook();
  resolve();
  const pixels = new Float32Array(width * height * 4);
  gl.readPixels(0, 0, width, height, gl.RGBA, gl.FLOAT, pixels);
  const t3 = performance.now();
  const error = gl.getError();
  if (error !== gl.NO_ERROR) throw new Error(`WebGL error 0x${error.toString(16)} after the render`);
  return {
    renderer: gl.getParameter(gl.getExtension("WEBGL_debug_renderer_info")?.UNMASKED_RENDERER_WEBGL ?? gl.RENDERER), version: gl.getParameter(gl.VERSION),
    msaa: { rgba32f_sample_counts_offered: Array.from(gl.getInternalformatParameter(gl.RENDERBUFFER, gl.RGBA32F, gl.SAMPLES) || []) },
    pixels: toBase64(new Uint8Array(pixels.buffer)),
    seconds: { gltf: (t1 - t0) / 1000, environment: (t2 - t1) / 1000, frame: (t3 - t2) / 1000 },
  };
};
window.pageReady = true;
