// viewer/src/viewer.js
// The script of every page `hmira view` writes: reads the meshes embedded in the page (a JSON
// scene plus base64 binary buffers, see viewer/README.md) and shows them with three.js, one or
// two side by side under one shared camera.
import {
    BufferAttribute,
    BufferGeometry,
    Color,
    DirectionalLight,
    DoubleSide,
    HemisphereLight,
    LineBasicMaterial,
    LineSegments,
    Mesh,
    MeshPhongMaterial,
    PerspectiveCamera,
    Points,
    PointsMaterial,
    Scene,
    Sphere,
    Vector3,
    WebGLRenderer,
} from 'three';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';
import { LineMaterial } from 'three/addons/lines/LineMaterial.js';
import { LineSegments2 } from 'three/addons/lines/LineSegments2.js';
import { LineSegmentsGeometry } from 'three/addons/lines/LineSegmentsGeometry.js';

// Colours the browser tests look for: keep them in step with tests/browser/test_viewer.py.
export const palette = {
    background: 0xf4f5f7,
    surface: 0x9fb4cf,
    edge: 0x30343a,
    boundary: 0xff2000,
    nonManifold: 0xff00ff,
    points: 0x2060c0,
};

// Above this many triangles the wireframe would turn the surface dark: edges start hidden.
const edgesShownUpTo = 20000;
// Above this many triangles multisampling is not worth its cost (see the renderer below).
const antialiasUpTo = 300000;
// Below this many faces a mesh is most likely a designed solid whose facets should show.
const flatShadedUpTo = 20000;

function decodeBase64(text) {
    if (typeof Uint8Array.fromBase64 === 'function') return Uint8Array.fromBase64(text);
    const binary = atob(text);
    const bytes = new Uint8Array(binary.length);
    for (let i = 0; i < binary.length; ++i) bytes[i] = binary.charCodeAt(i);
    return bytes;
}

function buffer(id, Type) {
    const element = document.getElementById(id);
    if (!element) return null;
    const bytes = decodeBase64(element.textContent.trim());
    element.textContent = '';  // the page keeps one copy of a large mesh, not two
    return new Type(bytes.buffer, bytes.byteOffset, bytes.byteLength / Type.BYTES_PER_ELEMENT);
}

// Each real polygon edge is owned by one triangle corner; edge_mask bit k of triangle t says
// that t's edge k (corner k to corner k+1) is one (fan diagonals of polygons are not).
function edgeIndices(triangles, mask) {
    let count = 0;
    for (let t = 0; t < mask.length; ++t) count += (mask[t] & 1) + ((mask[t] >> 1) & 1) + ((mask[t] >> 2) & 1);
    const lines = new Uint32Array(2 * count);
    let n = 0;
    for (let t = 0; t < mask.length; ++t) {
        const m = mask[t];
        if (m === 0) continue;
        const a = triangles[3 * t], b = triangles[3 * t + 1], c = triangles[3 * t + 2];
        if (m & 1) { lines[n++] = a; lines[n++] = b; }
        if (m & 2) { lines[n++] = b; lines[n++] = c; }
        if (m & 4) { lines[n++] = c; lines[n++] = a; }
    }
    return lines;
}

// Area-weighted vertex normals, in plain typed-array loops (a few times faster than
// BufferGeometry.computeVertexNormals on a million triangles).
function vertexNormals(positions, triangles) {
    const p = positions, normals = new Float32Array(p.length);
    for (let t = 0; t < triangles.length; t += 3) {
        const a = 3 * triangles[t], b = 3 * triangles[t + 1], c = 3 * triangles[t + 2];
        const ux = p[b] - p[a], uy = p[b + 1] - p[a + 1], uz = p[b + 2] - p[a + 2];
        const vx = p[c] - p[a], vy = p[c + 1] - p[a + 1], vz = p[c + 2] - p[a + 2];
        const nx = uy * vz - uz * vy, ny = uz * vx - ux * vz, nz = ux * vy - uy * vx;
        normals[a] += nx; normals[a + 1] += ny; normals[a + 2] += nz;
        normals[b] += nx; normals[b + 1] += ny; normals[b + 2] += nz;
        normals[c] += nx; normals[c + 1] += ny; normals[c + 2] += nz;
    }
    for (let i = 0; i < normals.length; i += 3) {
        const length = Math.hypot(normals[i], normals[i + 1], normals[i + 2]) || 1;
        normals[i] /= length; normals[i + 1] /= length; normals[i + 2] /= length;
    }
    return normals;
}

// Highlighted edges are drawn 3 px wide (quads, not GL lines, which are 1 px everywhere).
const highlightMaterials = [];
function wideLines(positions, indices, color, order) {
    const points = new Float32Array(3 * indices.length);
    for (let i = 0; i < indices.length; ++i)
        for (let k = 0; k < 3; ++k) points[3 * i + k] = positions.array[3 * indices[i] + k];
    const geometry = new LineSegmentsGeometry();
    geometry.setPositions(points);
    const material = new LineMaterial({ color, linewidth: 3 });
    highlightMaterials.push(material);
    const object = new LineSegments2(geometry, material);
    object.renderOrder = order;
    return object;
}

function lines(positions, indices, color, order) {
    const geometry = new BufferGeometry();
    geometry.setAttribute('position', positions);
    geometry.setIndex(new BufferAttribute(indices, 1));
    const object = new LineSegments(geometry, new LineBasicMaterial({ color, transparent: true, opacity: 0.55 }));
    object.renderOrder = order;
    return object;
}

// One embedded mesh: its scene, the objects the toggles switch, and its info line.
function buildMesh(entry, index) {
    const prefix = `hmira-m${index}-`;
    const positions = new BufferAttribute(buffer(prefix + 'positions', Float32Array), 3);
    const triangles = buffer(prefix + 'triangles', Uint32Array) || new Uint32Array(0);
    const normals = buffer(prefix + 'normals', Float32Array);
    const colors = buffer(prefix + 'colors', Uint8Array);
    const scene = new Scene();
    const part = { entry, scene, surface: null, edges: null, highlights: [] };

    if (triangles.length === 0) {
        const geometry = new BufferGeometry();
        geometry.setAttribute('position', positions);
        if (colors) geometry.setAttribute('color', new BufferAttribute(colors, 4, true));
        scene.add(new Points(geometry, new PointsMaterial({ color: colors ? 0xffffff : palette.points, size: 4, sizeAttenuation: false, vertexColors: !!colors })));
        geometry.computeBoundingSphere();
        part.bounds = geometry.boundingSphere;
        return part;
    }

    const geometry = new BufferGeometry();
    geometry.setAttribute('position', positions);
    geometry.setIndex(new BufferAttribute(triangles, 1));
    if (normals) geometry.setAttribute('normal', new BufferAttribute(normals, 3));
    if (colors) geometry.setAttribute('color', new BufferAttribute(colors, 4, true));
    const material = new MeshPhongMaterial({
        color: colors ? 0xffffff : palette.surface,
        vertexColors: !!colors,
        side: DoubleSide,
        shininess: 20,
        flatShading: !normals && triangles.length / 3 <= flatShadedUpTo,
        // Pushes the surface back so the edges drawn over it win the depth test.
        polygonOffset: true,
        polygonOffsetFactor: 1,
        polygonOffsetUnits: 1,
    });
    part.surface = new Mesh(geometry, material);
    scene.add(part.surface);
    geometry.computeBoundingSphere();
    part.bounds = geometry.boundingSphere;

    const mask = buffer(prefix + 'edge_mask', Uint8Array);
    part.makeEdges = () => {
        if (!part.edges && mask) {
            part.edges = lines(positions, edgeIndices(triangles, mask), palette.edge, 1);
            scene.add(part.edges);
        }
        return part.edges;
    };
    const boundary = buffer(prefix + 'boundary', Uint32Array);
    if (boundary && boundary.length) part.highlights.push(wideLines(positions, boundary, palette.boundary, 2));
    const nonManifold = buffer(prefix + 'non_manifold', Uint32Array);
    if (nonManifold && nonManifold.length) part.highlights.push(wideLines(positions, nonManifold, palette.nonManifold, 3));
    for (const h of part.highlights) scene.add(h);
    return part;
}

function infoText(entry) {
    const i = entry.info;
    const lines = [entry.name, `V ${i.vertices}   E ${i.edges}   F ${i.faces}`];
    if (i.faces > 0) lines.push(`genus ${i.genus}   ${i.closed ? 'closed' : 'open'}`);
    const marks = [];
    if (i.boundary_edges) marks.push(`<span style="color:#ff2000">&#9632;</span> ${i.boundary_edges} boundary edges`);
    if (i.non_manifold_edges) marks.push(`<span style="color:#ff00ff">&#9632;</span> ${i.non_manifold_edges} non-manifold edges`);
    if (i.faces === 0) marks.push('no faces: vertices shown as points');
    const escape = (s) => String(s).replace(/[&<>]/g, (c) => ({ '&': '&amp;', '<': '&lt;', '>': '&gt;' }[c]));
    return lines.map(escape).join('<br>') + (marks.length ? '<br>' + marks.join('<br>') : '');
}

function hashOptions() {
    const options = {};
    for (const pair of location.hash.replace(/^#/, '').split('&')) {
        const [key, value] = pair.split('=');
        if (key) options[decodeURIComponent(key)] = decodeURIComponent(value ?? '1');
    }
    return options;
}

const viewDirections = {
    iso: [1, 0.8, 1.2],
    front: [0, 0, 1],
    back: [0, 0, -1],
    left: [-1, 0, 0],
    right: [1, 0, 0],
    top: [0, 1, 0.0001],
    bottom: [0, -1, 0.0001],
};

function start() {
    const t0 = performance.now();
    const scene = JSON.parse(document.getElementById('hmira-scene').textContent);
    const parts = scene.meshes.map(buildMesh);
    const built = performance.now();
    const options = hashOptions();

    // Multisampling costs a software renderer (SwiftShader, headless Chromium) several times the
    // raster work; on a mesh this dense its triangles are smaller than a pixel anyway.
    const triangleCount = parts.reduce((n, p) => n + p.entry.triangles, 0);
    let renderer;
    try {
        renderer = new WebGLRenderer({ antialias: triangleCount <= antialiasUpTo });
    } catch (error) {
        const note = document.createElement('p');
        note.style.cssText = 'font:15px system-ui,sans-serif;margin:2em';
        note.textContent = `This page needs WebGL, which this browser does not offer (${error.message}).`;
        document.body.appendChild(note);
        window.hmiraError = String(error.message);
        throw error;
    }
    renderer.setPixelRatio(window.devicePixelRatio || 1);
    renderer.setSize(window.innerWidth, window.innerHeight);
    renderer.setClearColor(new Color(palette.background));
    renderer.setScissorTest(true);
    document.body.appendChild(renderer.domElement);

    // One camera for every half: orbiting one view orbits both, the linked comparison.
    const camera = new PerspectiveCamera(35, 1, 1e-3, 1e3);
    const light = new DirectionalLight(0xffffff, 2.2);
    light.position.set(0.5, 1, 2);
    camera.add(light);
    for (const p of parts) p.scene.add(new HemisphereLight(0xffffff, 0x505060, 1.0));
    const union = new Sphere();
    for (const p of parts) union.isEmpty() ? union.copy(p.bounds) : union.union(p.bounds);
    const radius = Math.max(union.radius, 1e-6);
    camera.near = radius / 100;
    camera.far = radius * 100;
    if (options.up === 'z') camera.up.set(0, 0, 1);  // before the controls, which orbit about camera.up
    const controls = new OrbitControls(camera, renderer.domElement);

    function setView(name) {
        const d = viewDirections[name] || viewDirections.iso;
        // #up=z (volumes, terrains): the same views with z up instead of y.
        const zUp = options.up === 'z';
        const direction = (zUp ? new Vector3(d[0], -d[2], d[1]) : new Vector3(...d)).normalize();
        const aspect = renderer.domElement.clientWidth / parts.length / Math.max(1, renderer.domElement.clientHeight);
        const halfFov = (camera.fov * Math.PI) / 360;
        // Distance at which the bounding sphere fits both the height and the width of a half.
        const fit = radius / Math.sin(Math.min(halfFov, Math.atan(Math.tan(halfFov) * aspect)));
        controls.target.copy(union.center);
        camera.position.copy(union.center).addScaledVector(direction, fit * 1.2);
        camera.lookAt(union.center);
        controls.update();
        requestRender();
    }

    const state = {
        smooth: options.shading ? options.shading === 'smooth' : parts.some((p) => p.surface && !p.surface.material.flatShading),
        edges: options.edges ? options.edges !== '0' : parts.every((p) => !p.surface || p.entry.triangles <= edgesShownUpTo),
        highlights: options.highlights ? options.highlights !== '0' : true,
    };
    function apply() {
        for (const p of parts) {
            if (p.surface) {
                p.surface.material.flatShading = !state.smooth;
                p.surface.material.needsUpdate = true;
                const geometry = p.surface.geometry;
                if (state.smooth && !geometry.getAttribute('normal'))
                    geometry.setAttribute('normal', new BufferAttribute(vertexNormals(geometry.getAttribute('position').array, geometry.getIndex().array), 3));
                if (state.edges) p.makeEdges();
                if (p.edges) p.edges.visible = state.edges;
            }
            for (const h of p.highlights) h.visible = state.highlights;
        }
        requestRender();
    }

    let pending = false;
    function render() {
        pending = false;
        const width = renderer.domElement.clientWidth, height = renderer.domElement.clientHeight;
        const half = Math.floor(width / parts.length);
        camera.aspect = half / Math.max(1, height);
        camera.updateProjectionMatrix();
        for (const m of highlightMaterials) m.resolution.set(half, height);
        parts.forEach((p, i) => {
            renderer.setViewport(i * half, 0, half, height);
            renderer.setScissor(i * half, 0, half, height);
            p.scene.add(camera);  // the headlight rides on the camera, in whichever scene draws
            renderer.render(p.scene, camera);
        });
    }
    function requestRender() {
        if (pending) return;
        pending = true;
        requestAnimationFrame(render);
    }
    controls.addEventListener('change', requestRender);
    window.addEventListener('resize', () => {
        renderer.setSize(window.innerWidth, window.innerHeight);
        requestRender();
    });

    // The corner panels: one info box per mesh, the toggles once.
    parts.forEach((p, i) => {
        const box = document.createElement('div');
        box.className = 'hmira-ui hmira-info';
        box.style.left = `calc(${(100 * i) / parts.length}% + 10px)`;
        box.innerHTML = infoText(p.entry);
        document.body.appendChild(box);
    });
    const panel = document.createElement('div');
    panel.className = 'hmira-ui hmira-controls';
    const toggles = [
        ['smooth', 'smooth shading (s)'],
        ['edges', 'edges (e)'],
        ['highlights', 'boundary / non-manifold (b)'],
    ];
    for (const [key, label] of toggles) {
        const row = document.createElement('label');
        const box = document.createElement('input');
        box.type = 'checkbox';
        box.checked = state[key];
        box.dataset.key = key;
        box.addEventListener('change', () => {
            state[key] = box.checked;
            apply();
        });
        row.append(box, ' ' + label);
        panel.appendChild(row);
    }
    const views = document.createElement('div');
    for (const name of ['iso', 'front', 'top', 'right']) {
        const button = document.createElement('button');
        button.textContent = name;
        button.addEventListener('click', () => setView(name));
        views.appendChild(button);
    }
    panel.appendChild(views);
    document.body.appendChild(panel);
    window.addEventListener('keydown', (event) => {
        const key = { s: 'smooth', e: 'edges', b: 'highlights' }[event.key];
        if (key) {
            state[key] = !state[key];
            panel.querySelector(`input[data-key="${key}"]`).checked = state[key];
            apply();
        } else if (event.key === 'r') {
            setView(options.view);
        }
    });

    apply();
    setView(options.view);
    const ready = performance.now();
    // The flag tests and screenshots wait for: set once the first frame has been drawn.
    requestAnimationFrame(() => {
        const frame = performance.now();
        render();
        const drawn = performance.now();
        requestAnimationFrame(() => {
            window.hmiraTimings = { build_ms: built - t0, ready_ms: ready - t0, frame_start_ms: frame - t0, render_call_ms: drawn - t0, first_frame_ms: performance.now() - t0 };
            window.hmiraRenderDone = true;
        });
    });
    window.hmiraViewer = { setView, state, apply, parts, renderer, camera };
}

start();
