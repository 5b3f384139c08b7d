// The 3D view of an object page or an upload: the surface of view.json (argtool view-data) turned
// with the mouse, shaded with its own colours or texture, mu or its nodes at a level, the Reeb
// graph's nodes on demand, and a click on a node's disc or on the surface picks that node (search
// by that part).
import * as THREE from "three";
import { OrbitControls } from "three/addons/controls/OrbitControls.js";

const box = document.getElementById("view3d");
const message = document.getElementById("view-message");
const note = document.getElementById("view-note");
const controlsForm = document.getElementById("view-controls");
const colourChoice = document.getElementById("view-colour");
const graphChoice = document.getElementById("view-graph");
const levelChoice = document.getElementById("view-level");
const partLink = document.getElementById("part-link");

// What mu looks like in the server's pictures (render/colour_map: Turbo without its darkest
// ends), as a few stops interpolated linearly.
const MU_STOPS = [
  [0.0, [65, 69, 171]], [0.15, [57, 130, 252]], [0.3, [27, 207, 212]], [0.45, [97, 252, 108]],
  [0.55, [164, 252, 60]], [0.7, [237, 208, 58]], [0.85, [251, 128, 34]], [1.0, [204, 44, 7]],
];
// Colours of nodes that stay apart from each other (render/colour_map's pair colours).
const NODE_COLOURS = [
  [31, 119, 180], [255, 127, 14], [44, 160, 44], [214, 39, 40], [148, 103, 189], [140, 86, 75],
  [227, 119, 194], [188, 189, 34], [23, 190, 207], [174, 199, 232], [255, 187, 120], [152, 223, 138],
];
const CLAY = [214, 212, 206];
const PICKED = [255, 214, 0];

function muColour(t) {
  t = Math.min(1, Math.max(0, t));
  for (let i = 1; i < MU_STOPS.length; ++i) {
    const [t1, c1] = MU_STOPS[i];
    if (t <= t1) {
      const [t0, c0] = MU_STOPS[i - 1];
      const k = (t - t0) / (t1 - t0);
      return c0.map((x, j) => x + k * (c1[j] - x));
    }
  }
  return MU_STOPS[MU_STOPS.length - 1][1];
}

// 0..255 sRGB to three's linear working colours, as [r, g, b].
const scratch = new THREE.Color();
function linear(rgb) {
  scratch.setRGB(rgb[0] / 255, rgb[1] / 255, rgb[2] / 255, THREE.SRGBColorSpace);
  return [scratch.r, scratch.g, scratch.b];
}

function nodeColour(n) {
  const c = NODE_COLOURS[n % NODE_COLOURS.length];
  const k = Math.floor(n / NODE_COLOURS.length) % 2 ? 0.7 : 1;
  return c.map((x) => x * k);
}

function fail(text) {
  box.dataset.state = "error";
  box.hidden = true;
  controlsForm.hidden = true;
  message.textContent = text;
  message.hidden = false;
}

// The ARG's frame has the principal axes on x, y, z, the longest first. view.json's canonical
// up (the side the object rests on best is down) and front become three's y and z, so that the
// camera, on +z, starts from the front with the object upright; without them x is drawn upright.
let axes = [[0, 1, 0], [1, 0, 0], [0, 0, -1]];
function frameAxes(data) {
  const u = data.up, f = data.front;
  if (!u || !f) return axes;
  const right = [u[1] * f[2] - u[2] * f[1], u[2] * f[0] - u[0] * f[2], u[0] * f[1] - u[1] * f[0]];
  return [right, u, f];
}
function upright(p, i) {
  return axes.map((a) => a[0] * p[i] + a[1] * p[i + 1] + a[2] * p[i + 2]);
}

// Why the view shows colours where the file has a texture: view.json's reason, or the browser's.
function say(text) {
  if (!note || !text) return;
  note.textContent = text;
  note.hidden = false;
}

const WRAPS = { repeat: THREE.RepeatWrapping, clamp: THREE.ClampToEdgeWrapping, mirror: THREE.MirroredRepeatWrapping };

function show(data) {
  axes = frameAxes(data);
  // An upload's page does not know its levels: they come with its view.
  if (levelChoice.options.length === 0) {
    const want = Math.min(Number(box.dataset.level || 2), data.levels.length - 1);
    data.levels.forEach((_, l) => {
      levelChoice.add(new Option(String(l), String(l), l === want, l === want));
    });
  }
  const faces = data.faces, positions = data.positions, faceCount = faces.length / 3;
  // With textures, the faces of texture 0 are drawn first (material 0's group), then those of
  // texture 1, and so on, then the faces without one: slot i of the geometry draws face order[i].
  const mapped = Boolean(data.textures && data.textures.length && data.uvs && data.face_textures);
  const textureOf = mapped ? data.face_textures : null;
  const order = [];
  const groups = [];
  if (mapped) {
    const buckets = data.textures.map(() => []), bare = [];
    for (let f = 0; f < faceCount; ++f) (textureOf[f] >= 0 ? buckets[textureOf[f]] : bare).push(f);
    buckets.concat([bare]).forEach((bucket, m) => {
      groups.push([order.length, bucket.length, m]);
      for (const f of bucket) order.push(f);
    });
  } else {
    for (let f = 0; f < faceCount; ++f) order.push(f);
  }
  const position = new Float32Array(faceCount * 9);
  let radius = 0;
  for (let i = 0; i < faceCount; ++i) {
    for (let k = 0; k < 3; ++k) {
      const v = upright(positions, 3 * faces[3 * order[i] + k]);
      position.set(v, 9 * i + 3 * k);
      radius = Math.max(radius, Math.hypot(v[0], v[1], v[2]));
    }
  }
  const geometry = new THREE.BufferGeometry();
  geometry.setAttribute("position", new THREE.BufferAttribute(position, 3));
  geometry.computeVertexNormals();  // corners not shared: flat shading, facets as the file has them
  const colour = new THREE.BufferAttribute(new Float32Array(faceCount * 9), 3);
  geometry.setAttribute("color", colour);
  const plain = new THREE.MeshLambertMaterial({ vertexColors: true, side: THREE.DoubleSide });
  // One material per texture; each gets its map once its image has loaded (its faces show
  // their colours until then).
  const textured = mapped ? data.textures.map(() => new THREE.MeshLambertMaterial({
    vertexColors: true, side: THREE.DoubleSide })) : [];
  const maps = textured.map(() => null);
  if (mapped) {
    const uv = new Float32Array(faceCount * 6);
    for (let i = 0; i < faceCount; ++i) {
      const f = order[i];
      if (textureOf[f] >= 0) uv.set(data.uvs.slice(6 * f, 6 * f + 6), 6 * i);
    }
    geometry.setAttribute("uv", new THREE.BufferAttribute(uv, 2));
    for (const [start, count, m] of groups) geometry.addGroup(3 * start, 3 * count, m);
  }
  box.dataset.texture = mapped ? "loading" : "none";
  say(data.texture_note);
  const surface = new THREE.Mesh(geometry, mapped ? [...textured, plain] : plain);

  const scene = new THREE.Scene();
  scene.background = new THREE.Color(0xffffff);
  scene.add(surface);
  scene.add(new THREE.HemisphereLight(0xffffff, 0x606060, 1.6));
  const key = new THREE.DirectionalLight(0xffffff, 1.8);
  key.position.set(-1, 1.5, 2);
  scene.add(key);
  const graph = new THREE.Group();
  scene.add(graph);

  const size = box.clientWidth || 480;
  const renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
  renderer.setPixelRatio(1);
  renderer.setSize(size, box.clientHeight || size);
  box.appendChild(renderer.domElement);
  const camera = new THREE.PerspectiveCamera(35, 1, radius / 100, radius * 100);
  camera.position.set(0, 0, (1.15 * radius) / Math.sin((35 / 2) * (Math.PI / 180)));
  const controls = new OrbitControls(camera, renderer.domElement);
  const render = () => renderer.render(scene, camera);
  controls.addEventListener("change", render);

  let picked = Number(box.dataset.part || -1);
  box.dataset.picked = String(picked);
  const level = () => Number(levelChoice.value);

  // A texture shows through its factor (a glTF material's baseColorFactor; white for an OBJ),
  // taken as the ARG takes it: multiplying the texture's 0..1 sRGB values, as the untextured
  // faces' colours already carry their factor. A picked part tints it; mu and the nodes replace it.
  const factors = mapped ? data.textures.map((t) => (t.factor || [1, 1, 1]).map((x) => 255 * x)) : [];
  function paint() {
    const mode = colourChoice.value, nodes = data.levels[level()].face_nodes, c = colour.array;
    textured.forEach((material, m) => {
      const map = mode === "own" ? maps[m] : null;
      if (material.map !== map) {
        material.map = map;
        material.needsUpdate = true;
      }
    });
    box.dataset.maps = String(textured.filter((material) => material.map).length);
    for (let i = 0; i < faceCount; ++i) {
      const f = order[i], t = mapped ? textureOf[f] : -1;
      for (let k = 0; k < 3; ++k) {
        const v = faces[3 * f + k];
        let rgb;
        if (picked >= 0 && nodes[f] === picked) rgb = PICKED;
        else if (mode === "mu") rgb = muColour(data.mu[v]);
        else if (mode === "nodes") rgb = nodes[f] >= 0 ? nodeColour(nodes[f]) : CLAY;
        else if (t >= 0 && maps[t]) rgb = factors[t];
        else rgb = data.face_colours ? data.face_colours.slice(3 * f, 3 * f + 3) : CLAY;
        c.set(linear(rgb), 9 * i + 3 * k);
      }
    }
    colour.needsUpdate = true;
  }

  // The nodes of the chosen level as discs at their barycentres (area as in arg_svg), their
  // edges as lines, drawn over the surface (a barycentre usually lies inside its part).
  function drawGraph() {
    graph.clear();
    const shown = graphChoice.checked, at = data.levels[level()];
    const count = at.areas.length;
    box.dataset.nodes = shown ? String(count) : "0";
    if (!shown) return;
    const centre = (n) => new THREE.Vector3(...upright(at.centres, 3 * n));
    const edges = [];
    for (let i = 0; i < at.edges.length; i += 2) edges.push(centre(at.edges[i]), centre(at.edges[i + 1]));
    const lines = new THREE.LineSegments(new THREE.BufferGeometry().setFromPoints(edges),
                                         new THREE.LineBasicMaterial({ color: 0x222222, depthTest: false }));
    lines.renderOrder = 1;
    graph.add(lines);
    for (let n = 0; n < count; ++n) {
      const r = radius * (0.03 + 0.12 * Math.sqrt(at.areas[n]));
      const disc = new THREE.Mesh(new THREE.SphereGeometry(r, 16, 12), new THREE.MeshBasicMaterial({
        color: new THREE.Color(...linear(nodeColour(n))), depthTest: false,
      }));
      disc.position.copy(centre(n));
      disc.userData.node = n;
      disc.renderOrder = 2;
      graph.add(disc);
    }
  }

  function update() {
    paint();
    drawGraph();
    box.dataset.mode = colourChoice.value;
    render();
  }

  // A click (a press and release without a drag) picks the node of the surface under it.
  const ray = new THREE.Raycaster();
  let down = null;
  renderer.domElement.addEventListener("pointerdown", (e) => { down = [e.clientX, e.clientY]; });
  renderer.domElement.addEventListener("pointerup", (e) => {
    if (!down || Math.hypot(e.clientX - down[0], e.clientY - down[1]) > 4) return;
    const rect = renderer.domElement.getBoundingClientRect();
    ray.setFromCamera(new THREE.Vector2(((e.clientX - rect.left) / rect.width) * 2 - 1,
                                        -((e.clientY - rect.top) / rect.height) * 2 + 1), camera);
    // A node's disc is drawn over the surface, so a click on it picks it wherever it lies.
    const disc = ray.intersectObjects(graph.children.filter((o) => o.isMesh))[0];
    const hit = disc ? null : ray.intersectObject(surface)[0];
    picked = disc ? disc.object.userData.node : hit ? data.levels[level()].face_nodes[order[hit.faceIndex]] : -1;
    box.dataset.picked = String(picked);
    if (partLink) {
      partLink.hidden = picked < 0;
      partLink.href = `/object/${box.dataset.object}/part?level=${level()}&node=${picked}`;
      partLink.textContent = `objects with a part like node ${picked} of level ${level()}`;
    }
    update();
  });

  colourChoice.addEventListener("change", update);
  graphChoice.addEventListener("change", update);
  levelChoice.addEventListener("change", () => { picked = -1; if (partLink) partLink.hidden = true; update(); });
  update();
  box.dataset.state = "ready";
  if (mapped) {
    // The texture route serves the images view.json describes: beside it, as .../texture/I.
    // Each image is loaded once; a texture that wraps it otherwise shares it through a clone.
    let left = data.images.length, failed = false;
    data.images.forEach((_, i) => {
      new THREE.TextureLoader().load(box.dataset.src.replace(/view\.json$/, `texture/${i}`), (loaded) => {
        loaded.colorSpace = THREE.SRGBColorSpace;
        loaded.anisotropy = renderer.capabilities.getMaxAnisotropy();
        let first = true;
        data.textures.forEach((t, m) => {
          if (t.image !== i) return;
          const map = first ? loaded : loaded.clone();
          first = false;
          map.wrapS = WRAPS[t.wrap_s] || THREE.RepeatWrapping;
          map.wrapT = WRAPS[t.wrap_t] || THREE.RepeatWrapping;
          map.needsUpdate = true;
          maps[m] = map;
        });
        if (--left === 0) box.dataset.texture = failed ? "failed" : "mapped";
        update();
      }, undefined, () => {
        failed = true;
        if (--left === 0) box.dataset.texture = "failed";
        say("A texture could not be loaded: its faces show the colours taken from it.");
      });
    });
  }
}

async function start() {
  let response, data;
  try {
    response = await fetch(box.dataset.src);
    data = await response.json();
  } catch (error) {
    fail(`The 3D view could not be loaded: ${error}`);
    return;
  }
  if (!response.ok || data.error) {
    fail(data.error || `The 3D view could not be loaded: HTTP ${response.status}`);
    return;
  }
  try {
    show(data);
  } catch (error) {
    fail(`The 3D view could not be drawn: ${error}`);
  }
}

start();
