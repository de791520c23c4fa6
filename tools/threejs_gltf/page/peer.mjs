// The page ../render.mjs drives: one glTF render with three.js's own WebGLRenderer, the way
// model-viewer uses it (GLTFLoader's materials, the environment prefiltered by PMREMGenerator
// as scene.environment, no background), read back as linear float radiance.
//
// Facts from three.js r187's source (node_modules/three), on which the settings below rest:
//  * Rendering into a WebGLRenderTarget, every material writes the working colour space
//    (linear sRGB) without tone mapping: src/renderers/webgl/WebGLPrograms.js (outputColorSpace
//    is ColorManagement.workingColorSpace unless the target is the canvas or an XR target) and
//    src/renderers/WebGLRenderer.js (toneMapping applies to the canvas only). toneMapping is
//    set to NoToneMapping all the same.
//  * scene.environment reaches MeshStandard/PhysicalMaterial as envMap with envMapRotation =
//    scene.environmentRotation (WebGLRenderer.js, "materialProperties.envMapRotation") and
//    envMapIntensity = scene.environmentIntensity; WebGLMaterials.js uploads the rotation's
//    TRANSPOSE, so the shader samples the environment along R(rotation)^T * world direction.
//  * The equirect image is sampled by equirectUv (src/renderers/shaders/ShaderChunk/
//    common.glsl.js): u = atan(d.z, d.x) / 2pi + 0.5, v = asin(d.y) / pi + 0.5, v = 1 being the
//    image's top row (EXRLoader writes rows bottom-up, flipY false: examples/jsm/loaders/
//    EXRLoader.js, "outLineOffset"). pbrlab's u is atan2(d.x, -d.z) / 2pi: the same turning
//    sense, three.js's u being pbrlab's plus 1/4. Sampling along R_y(-theta) d adds theta / 2pi
//    to three.js's u, so environmentRotation.y = -pi/2 makes three.js see pbrlab's sky
//    (render.mjs passes the angle; pbrlab.checking.fidelity.check_staging is the proof).
//  * The transmission pass (WebGLRenderer.js, renderTransmissionPass) renders the opaque
//    objects into its own half-float, 4x multisampled target of the current viewport's size
//    and restores the current render target after it, so it works when the frame itself goes
//    into a render target. With a clear alpha below 1 it clears that copy to white at alpha
//    0.5 (three.js's stand-in for the page behind a transparent canvas): that is what a
//    transmissive surface shows where nothing opaque is behind it, as in model-viewer,
//    unless the spec gives transmissionBackground (useTransmissionBackground below).
//  * Blending (NormalBlending, material.premultipliedAlpha false) is SRC_ALPHA,
//    ONE_MINUS_SRC_ALPHA for colour and ONE, ONE_MINUS_SRC_ALPHA for alpha over a clear of
//    (0, 0, 0, 0), and the multisample resolve averages colour and alpha alike: the target
//    holds colour PREMULTIPLIED by coverage, as the canvas (premultipliedAlpha: true) is
//    composited. render.mjs divides it out.
import * as THREE from "three";
import { GLTFLoader } from "three/addons/loaders/GLTFLoader.js";
import { EXRLoader } from "three/addons/loaders/EXRLoader.js";
import { DRACOLoader } from "three/addons/loaders/DRACOLoader.js";
import { KTX2Loader } from "three/addons/loaders/KTX2Loader.js";
import { MeshoptDecoder } from "three/addons/libs/meshopt_decoder.module.js";

// The decoders three.js ships beside GLTFLoader (examples/jsm/libs, served under /three/), set
// as model-viewer sets them: without them GLTFLoader draws no KHR_draco_mesh_compression mesh,
// no KHR_texture_basisu texture and no EXT_meshopt_compression buffer (it logs "Couldn't load
// texture" and draws the material without it), and a comparison would be of a different model.
function gltfLoader(renderer) {
  const draco = new DRACOLoader().setDecoderPath("/three/examples/jsm/libs/draco/gltf/");
  const ktx2 = new KTX2Loader().setTranscoderPath("/three/examples/jsm/libs/basis/").detectSupport(renderer);
  const loader = new GLTFLoader().setDRACOLoader(draco).setKTX2Loader(ktx2).setMeshoptDecoder(MeshoptDecoder);
  return { loader, dispose: () => { draco.dispose(); ktx2.dispose(); } };
}

function toBase64(bytes) {
  let text = "";
  for (let i = 0; i < bytes.length; i += 0x8000) text += String.fromCharCode(...bytes.subarray(i, i + 0x8000));
  return btoa(text);
}

// What a transmissive surface shows where no opaque object is behind it. three.js r187's
// transmission pass (WebGLRenderer.js, renderTransmissionPass) clears its copy of the opaque
// objects with the renderer's clear colour, or, under a clear alpha below 1 as here, with
// setClearColor(0xffffff, 0.5): the page behind a transparent canvas, so glass over nothing
// shows white. KHR_materials_transmission's light from behind is the scene's, the environment
// where nothing else is (as pbrlab and the Sample Viewer draw it). Given the constant sky's
// linear colour, that one clear is made the sky at alpha 1 (the call is recognised by its
// arguments; the frame's own clear, (0, 0, 0, 0), is untouched, and the pass restores it).
function useTransmissionBackground(renderer, rgb) {
  const sky = new THREE.Color().setRGB(rgb[0], rgb[1], rgb[2], THREE.LinearSRGBColorSpace);
  const setClearColor = renderer.setClearColor.bind(renderer);
  renderer.setClearColor = (color, alpha) =>
    (color === 0xffffff && alpha === 0.5) ? setClearColor(sky, 1) : setClearColor(color, alpha);
}

// The sample counts the implementation offers for a float colour renderbuffer (WebGL2
// getInternalformatParameter), to say whether the requested multisampling can take effect.
function floatSampleCounts(gl, internalFormat) {
  return Array.from(gl.getInternalformatParameter(gl.RENDERBUFFER, internalFormat, gl.SAMPLES) || []);
}

// spec: {gltf: url, environment: url (linear equirect .exr) | null, environmentRotationRad,
//        environmentIntensity, size: [w, h], msaa: samples,
//        camera: {eye, target, up, yfov_deg, znear, zfar}}
window.renderGltf = async (spec) => {
  const [width, height] = spec.size;
  const canvas = document.createElement("canvas");
  canvas.width = width;
  canvas.height = height;
  // The canvas is never drawn to: the frame goes into `target` below.
  const renderer = new THREE.WebGLRenderer({ canvas, antialias: false, alpha: true });
  renderer.setPixelRatio(1);
  renderer.setSize(width, height, false);
  renderer.toneMapping = THREE.NoToneMapping;
  renderer.toneMappingExposure = 1.0;
  renderer.outputColorSpace = THREE.LinearSRGBColorSpace;
  if (spec.transmissionBackground) useTransmissionBackground(renderer, spec.transmissionBackground);
  const gl = renderer.getContext();
  if (!gl.getExtension("EXT_color_buffer_float")) throw new Error("EXT_color_buffer_float is missing");
  if (!gl.getExtension("EXT_float_blend")) throw new Error("EXT_float_blend is missing (blending into RGBA32F)");
  const requestedSamples = spec.msaa ?? 4;
  const offered = floatSampleCounts(gl, gl.RGBA32F);
  const target = new THREE.WebGLRenderTarget(width, height, {
    type: THREE.FloatType, format: THREE.RGBAFormat, colorSpace: THREE.LinearSRGBColorSpace,
    samples: requestedSamples, depthBuffer: true, stencilBuffer: false, generateMipmaps: false,
    minFilter: THREE.NearestFilter, magFilter: THREE.NearestFilter,
  });

  const scene = new THREE.Scene();
  scene.background = null;
  const t0 = performance.now();
  const decoders = gltfLoader(renderer);
  const gltf = await decoders.loader.loadAsync(spec.gltf);
  decoders.dispose();
  scene.add(gltf.scene);
  const t1 = performance.now();
  let pmrem = null;
  let environment = null;
  let environmentSize = null;
  if (spec.environment) {
    const equirect = await new EXRLoader().loadAsync(spec.environment);
    equirect.mapping = THREE.EquirectangularReflectionMapping;
    environmentSize = [equirect.image.width, equirect.image.height];
    pmrem = new THREE.PMREMGenerator(renderer);
    environment = pmrem.fromEquirectangular(equirect);
    equirect.dispose();
    scene.environment = environment.texture;
    scene.environmentIntensity = spec.environmentIntensity ?? 1.0;
    scene.environmentRotation.set(0, spec.environmentRotationRad, 0);
  }
  const t2 = performance.now();

  const c = spec.camera;
  const camera = new THREE.PerspectiveCamera(c.yfov_deg, width / height, c.znear, c.zfar);
  camera.position.set(...c.eye);
  camera.up.set(...c.up);
  camera.lookAt(new THREE.Vector3(...c.target));
  camera.updateMatrixWorld(true);

  renderer.setRenderTarget(target);
  renderer.setClearColor(0x000000, 0);
  renderer.clear();
  renderer.compile(scene, camera);
  const t3 = performance.now();
  renderer.render(scene, camera);
  const pixels = new Float32Array(width * height * 4);
  renderer.readRenderTargetPixels(target, 0, 0, width, height, pixels);
  const t4 = performance.now();
  const error = gl.getError();
  if (error !== gl.NO_ERROR) throw new Error(`WebGL error 0x${error.toString(16)} after the render`);
  const debugInfo = gl.getExtension("WEBGL_debug_renderer_info");
  const result = {
    renderer: gl.getParameter(debugInfo ? debugInfo.UNMASKED_RENDERER_WEBGL : gl.RENDERER),
    version: gl.getParameter(gl.VERSION), three: THREE.REVISION,
    msaa: { requested: requestedSamples, rgba32f_sample_counts_offered: offered,
            max_samples: renderer.capabilities.maxSamples },
    environment_size: environmentSize,  // PMREM's face size: the largest power of 2 <= width / 4
    pixels: toBase64(new Uint8Array(pixels.buffer)),
    seconds: { gltf: (t1 - t0) / 1000, environment: (t2 - t1) / 1000, compile: (t3 - t2) / 1000,
               frame: (t4 - t3) / 1000 },
  };
  if (pmrem) pmrem.dispose();
  if (environment) environment.dispose();
  target.dispose();
  renderer.dispose();
  return result;
};
window.pageReady = true;
