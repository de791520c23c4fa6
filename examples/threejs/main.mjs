// The three.js example: a pbrlab scene of analytic spheres, directional lights and a constant
// environment (scene.json, the file `pbrlab render` reads) drawn by three.js, each sphere a
// ShaderMaterial whose fragment shader is the amalgamated pbrlab library (`pbrlab amalgamate
// library_entry.glsl`) handed the exported DFG table (`pbrlab tables`, pbrlab_dfg.exr) through
// the library's PBR_DFG_LUT_LOOKUP hook. renderScene returns the linear radiance it drew
// (float RGBA, rows bottom to top), which tests/examples/test_threejs_example.py compares
// with `pbrlab render` of the same scene; showScene draws the same spheres on the page's canvas,
// tone mapped and sRGB encoded.
import * as THREE from "three";
import { EXRLoader } from "three/addons/loaders/EXRLoader.js";

const HERE = new URL(".", import.meta.url);
// The library reads the table at its own texture coordinates (docs/tables.md): the EXR,
// loaded by EXRLoader with its bottom row at v = 0, bilinear, clamped, no mips.
const DFG_HOOK = "uniform sampler2D u_dfg;\n" +
  "#define PBR_DFG_LUT_LOOKUP(NdotV, r) texture(u_dfg, pbr_dfg_lut_uv(NdotV, r)).rg\n";
const MAX_LIGHTS = 4;  // sphere.frag.glsl's
// The scene format's defaults (pbrlab schema) for the fields this example reads.
const DEFAULTS = { up: [0, 1, 0], fov_y_deg: 45, size: [512, 512], color: [1, 1, 1], intensity: 1,
                   albedo: [0.8, 0.8, 0.8], metallic: 0, smoothness: 0.5 };

async function text(url) {
  const response = await fetch(url);
  if (!response.ok) throw new Error(`${url}: HTTP ${response.status}`);
  return response.text();
}

async function loadDfg(url) {
  const table = await new EXRLoader().setDataType(THREE.FloatType).loadAsync(url);
  table.minFilter = THREE.LinearFilter;
  table.magFilter = THREE.LinearFilter;
  table.wrapS = table.wrapT = THREE.ClampToEdgeWrapping;
  table.generateMipmaps = false;
  table.colorSpace = THREE.NoColorSpace;  // data, not colour
  table.needsUpdate = true;
  return table;
}

function scaled(color, intensity) {
  return new THREE.Vector3(...color).multiplyScalar(intensity);
}

// The scene's camera and meshes, one ShaderMaterial per sphere; display: 1 for the on-screen view.
async function buildScene({ scene: sceneUrl, library: libraryUrl, dfg: dfgUrl }, display) {
  const [scene, library, vertex, fragment, dfg] = await Promise.all([
    text(sceneUrl).then(JSON.parse), text(libraryUrl), text(new URL("sphere.vert.glsl", HERE)),
    text(new URL("sphere.frag.glsl", HERE)), loadDfg(dfgUrl)]);
  const [width, height] = scene.camera.size ?? DEFAULTS.size;
  const camera = new THREE.PerspectiveCamera(scene.camera.fov_y_deg ?? DEFAULTS.fov_y_deg, width / height, 0.01, 1000);
  camera.position.set(...scene.camera.position);
  camera.up.set(...(scene.camera.up ?? DEFAULTS.up));
  camera.lookAt(...scene.camera.target);

  const lights = (scene.lights ?? []).map((light) => {
    if (light.type !== "directional") throw new Error(`this example draws directional lights only, not ${light.type}`);
    return { direction: new THREE.Vector3(...light.direction).normalize(),
             radiance: scaled(light.color ?? DEFAULTS.color, light.intensity ?? DEFAULTS.intensity) };
  });
  if (lights.length > MAX_LIGHTS) throw new Error(`at most ${MAX_LIGHTS} lights`);
  while (lights.length < MAX_LIGHTS) lights.push({ direction: new THREE.Vector3(0, 0, -1), radiance: new THREE.Vector3() });
  const env = scene.environment;
  if (env && !env.color) throw new Error("this example takes a constant environment ({\"color\": ...}) only");
  const environment = env ? scaled(env.color, env.intensity ?? 1) : new THREE.Vector3();

  const world = new THREE.Scene();
  for (const object of scene.objects) {
    if (!object.sphere) throw new Error("this example draws spheres only");
    const m = scene.materials[object.material];
    if ((m.workflow ?? "metallic") !== "metallic") throw new Error("this example takes the metallic workflow only");
    const { center, radius } = object.sphere;
    const material = new THREE.ShaderMaterial({
      glslVersion: THREE.GLSL3,
      vertexShader: vertex,
      fragmentShader: DFG_HOOK + library + "\n" + fragment,
      uniforms: {
        u_dfg: { value: dfg },
        u_sphere: { value: new THREE.Vector4(...center, radius) },
        u_albedo: { value: new THREE.Vector3(...(m.albedo ?? DEFAULTS.albedo)) },
        u_metallic: { value: m.metallic ?? DEFAULTS.metallic },
        u_smoothness: { value: m.smoothness ?? DEFAULTS.smoothness },
        u_environment: { value: environment },
        u_light_count: { value: (scene.lights ?? []).length },
        u_light_direction: { value: lights.map((l) => l.direction) },
        u_light_radiance: { value: lights.map((l) => l.radiance) },
        u_display: { value: display },
      },
    });
    // A bounding mesh, 10 % larger: the fragment shader finds the sphere itself.
    const mesh = new THREE.Mesh(new THREE.SphereGeometry(radius * 1.1, 64, 32), material);
    mesh.position.set(...center);
    world.add(mesh);
  }
  return { world, camera, width, height };
}

export async function renderScene(urls) {
  const { world, camera, width, height } = await buildScene(urls, 0);
  const renderer = new THREE.WebGLRenderer({ antialias: false });
  renderer.setPixelRatio(1);
  renderer.setSize(width, height, false);
  const target = new THREE.WebGLRenderTarget(width, height, { type: THREE.FloatType, depthBuffer: true,
                                                              minFilter: THREE.NearestFilter,
                                                              magFilter: THREE.NearestFilter });
  renderer.setRenderTarget(target);
  renderer.setClearColor(0x000000, 0);
  renderer.clear();
  renderer.render(world, camera);
  const pixels = new Float32Array(width * height * 4);
  renderer.readRenderTargetPixels(target, 0, 0, width, height, pixels);
  const gl = renderer.getContext();
  const info = gl.getExtension("WEBGL_debug_renderer_info");
  const name = info ? gl.getParameter(info.UNMASKED_RENDERER_WEBGL) : gl.getParameter(gl.RENDERER);
  renderer.dispose();
  return { width, height, pixels, renderer: name, three: THREE.REVISION };
}

// The page's view: the same scene on a visible canvas (8-bit, tone mapped, sRGB encoded).
export async function showScene(canvas, urls) {
  const { world, camera, width, height } = await buildScene(urls, 1);
  const renderer = new THREE.WebGLRenderer({ canvas, antialias: false });
  renderer.setPixelRatio(1);
  renderer.setSize(width, height, false);
  renderer.setClearColor(0x000000, 0);
  renderer.render(world, camera);
  return renderer;
}
