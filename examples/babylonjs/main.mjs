// The Babylon.js example: a pbrlab scene of analytic spheres, directional lights and a constant
// environment (scene.json, the file `pbrlab render` reads) drawn by Babylon.js, each sphere a
// ShaderMaterial whose fragment shader is the amalgamated pbrlab library exactly as `pbrlab
// amalgamate library_entry.glsl` writes it (Babylon.js's own preprocessor evaluates its
// conditionals: glsl/README.md, "One-level preprocessors"), handed the exported DFG table
// (`pbrlab tables`, pbrlab_dfg.exr) through the library's PBR_DFG_LUT_LOOKUP hook.
// renderScene returns the linear radiance it drew (float RGBA, rows bottom to top), which
// tests/examples/test_babylonjs_example.py compares with `pbrlab render` of the same scene;
// showScene draws the same spheres on the page's canvas, tone mapped and sRGB encoded.
import { Constants, Engine, Scene, FreeCamera, Vector3, Vector4, Color4, MeshBuilder, ShaderMaterial,
         RenderTargetTexture, Texture, ExrLoaderGlobalConfiguration, EXROutputType } from "@babylonjs/core";

const HERE = new URL(".", import.meta.url);
// Babylon.js's EXR loader decompresses ZIP with fflate, fetched from a CDN unless told where:
// the pinned copy in tools/babylonjs (the version the loader names). Float, not half, texels.
ExrLoaderGlobalConfiguration.FFLATEUrl = "/tools/babylonjs/node_modules/fflate/umd/index.js";
ExrLoaderGlobalConfiguration.DefaultOutputType = EXROutputType.Float;
// The library's DFG hook, declared above the library: an object-like macro naming a function
// (sphere.fragment.glsl defines it below the library, where pbr_dfg_lut_uv exists), since
// Babylon.js's preprocessor records `#define NAME VALUE` lines only, so the conditionals it
// evaluates itself would not see a function-like PBR_DFG_LUT_LOOKUP(NdotV, r) as defined.
const PRELUDE = "precision highp float;\nprecision highp int;\nprecision highp sampler2D;\n" +
  "uniform sampler2D u_dfg;\n" +
  "vec2 example_dfg_lookup(float NdotV, float perceptualRoughness);\n" +
  "#define PBR_DFG_LUT_LOOKUP example_dfg_lookup\n";
const MAX_LIGHTS = 4;  // sphere.fragment.glsl's
// The scene format's defaults (pbrlab schema) for the fields this example reads.
const DEFAULTS = { up: [0, 1, 0], fov_y_deg: 45, size: [512, 512], color: [1, 1, 1], intensity: 1,
                   albedo: [0.8, 0.8, 0.8], metallic: 0, smoothness: 0.5 };
const UNIFORMS = ["world", "viewProjection", "u_camera", "u_sphere", "u_albedo", "u_metallic", "u_smoothness",
                  "u_environment", "u_light_count", "u_light_direction", "u_light_radiance", "u_display"];

async function text(url) {
  const response = await fetch(url);
  if (!response.ok) throw new Error(`${url}: HTTP ${response.status}`);
  return response.text();
}

function loadDfg(url, scene) {
  return new Promise((resolve, reject) => {
    const table = new Texture(url, scene, {
      noMipmap: true, invertY: false, samplingMode: Texture.BILINEAR_SAMPLINGMODE,
      onLoad: () => resolve(table), onError: (message) => reject(new Error(`${url}: ${message}`)) });
    table.wrapU = table.wrapV = Texture.CLAMP_ADDRESSMODE;
    table.gammaSpace = false;  // data, not colour
  });
}

function scaled(color, intensity) {
  return color.map((c) => c * intensity);
}

// The scene drawn with one ShaderMaterial per sphere; display: 1 for the on-screen view.
async function buildScene(engine, urls, display) {
  const [data, library, vertex, fragment] = await Promise.all([
    text(urls.scene).then(JSON.parse), text(urls.library), text(new URL("sphere.vertex.glsl", HERE)),
    text(new URL("sphere.fragment.glsl", HERE))]);
  const scene = new Scene(engine);
  scene.useRightHandedSystem = true;  // pbrlab's world (docs/conventions.md)
  scene.clearColor = new Color4(0, 0, 0, 0);
  const dfg = await loadDfg(urls.dfg, scene);
  const cam = data.camera;
  const camera = new FreeCamera("camera", new Vector3(...cam.position), scene);
  camera.upVector = new Vector3(...(cam.up ?? DEFAULTS.up));
  camera.setTarget(new Vector3(...cam.target));
  camera.fov = (cam.fov_y_deg ?? DEFAULTS.fov_y_deg) * Math.PI / 180;  // vertical: Babylon's default fovMode
  camera.minZ = 0.01;
  camera.maxZ = 1000;

  const lights = (data.lights ?? []).map((light) => {
    if (light.type !== "directional") throw new Error(`this example draws directional lights only, not ${light.type}`);
    return { direction: new Vector3(...light.direction).normalize().asArray(),
             radiance: scaled(light.color ?? DEFAULTS.color, light.intensity ?? DEFAULTS.intensity) };
  });
  const lightCount = lights.length;
  if (lightCount > MAX_LIGHTS) throw new Error(`at most ${MAX_LIGHTS} lights`);
  while (lights.length < MAX_LIGHTS) lights.push({ direction: [0, 0, -1], radiance: [0, 0, 0] });
  const env = data.environment;
  if (env && !env.color) throw new Error("this example takes a constant environment ({\"color\": ...}) only");
  const environment = env ? scaled(env.color, env.intensity ?? 1) : [0, 0, 0];

  const materials = [];
  for (const [index, object] of data.objects.entries()) {
    if (!object.sphere) throw new Error("this example draws spheres only");
    const m = data.materials[object.material];
    if ((m.workflow ?? "metallic") !== "metallic") throw new Error("this example takes the metallic workflow only");
    const { center, radius } = object.sphere;
    const material = new ShaderMaterial(`sphere${index}`, scene,
      { vertexSource: vertex, fragmentSource: PRELUDE + library + "\n" + fragment },
      { attributes: ["position"], uniforms: UNIFORMS, samplers: ["u_dfg"] });
    material.setTexture("u_dfg", dfg);
    material.setVector3("u_camera", camera.position);
    material.setVector4("u_sphere", new Vector4(...center, radius));
    material.setVector3("u_albedo", new Vector3(...(m.albedo ?? DEFAULTS.albedo)));
    material.setFloat("u_metallic", m.metallic ?? DEFAULTS.metallic);
    material.setFloat("u_smoothness", m.smoothness ?? DEFAULTS.smoothness);
    material.setVector3("u_environment", new Vector3(...environment));
    material.setInt("u_light_count", lightCount);
    material.setArray3("u_light_direction", lights.flatMap((l) => l.direction));
    material.setArray3("u_light_radiance", lights.flatMap((l) => l.radiance));
    material.setInt("u_display", display);
    material.backFaceCulling = false;
    // A bounding mesh, 10 % larger: the fragment shader finds the sphere itself.
    const mesh = MeshBuilder.CreateSphere(`sphere${index}`, { diameter: 2.2 * radius, segments: 64 }, scene);
    mesh.position = new Vector3(...center);
    mesh.material = material;
    materials.push({ material, mesh });
  }
  await compiled(materials);
  return { scene, camera, size: cam.size ?? DEFAULTS.size, meshes: materials.map((x) => x.mesh) };
}

// Resolves once every material's program is linked; rejects with the compiler's log.
function compiled(materials) {
  return Promise.all(materials.map(({ material, mesh }) => new Promise((resolve, reject) => {
    material.onError = (effect, errors) => reject(new Error(`${material.name}: ${errors}`));
    const poll = () => (material.isReady(mesh) ? resolve() : setTimeout(poll, 20));
    poll();
  })));
}

export async function renderScene(urls) {
  const canvas = document.createElement("canvas");
  const engine = new Engine(canvas, false, { preserveDrawingBuffer: true, premultipliedAlpha: false });
  try {
    const { scene, camera, size: [width, height], meshes } = await buildScene(engine, urls, 0);
    const target = new RenderTargetTexture("radiance", { width, height }, scene, {
      generateMipMaps: false, type: Constants.TEXTURETYPE_FLOAT, samplingMode: Texture.NEAREST_SAMPLINGMODE,
      generateDepthBuffer: true });
    target.renderList = meshes;
    target.activeCamera = camera;
    target.clearColor = new Color4(0, 0, 0, 0);
    target.render();
    const pixels = await target.readPixels();
    const gl = engine._gl;
    const info = gl.getExtension("WEBGL_debug_renderer_info");
    const name = info ? gl.getParameter(info.UNMASKED_RENDERER_WEBGL) : gl.getParameter(gl.RENDERER);
    return { width, height, pixels: new Float32Array(pixels.buffer, pixels.byteOffset, width * height * 4),
             renderer: name, babylon: Engine.Version };
  } finally {
    engine.dispose();
  }
}

// The page's view: the same scene on a visible canvas (8-bit, tone mapped, sRGB encoded).
export async function showScene(canvas, urls) {
  const engine = new Engine(canvas, false, { preserveDrawingBuffer: true });
  const { scene, size: [width, height] } = await buildScene(engine, urls, 1);
  canvas.width = width;
  canvas.height = height;
  engine.resize();
  scene.render();
  return engine;
}
