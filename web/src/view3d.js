// The 3D view of a folding crease pattern (three.js). The flat sheet lies in the plane z = 0 in
// the pattern's own units, z pointing up like a table seen from above: the world coordinates are
// foldkit's, so contact points and displacements from the server are drawn as they come.
// Only geometry is rewritten while folding: setPattern() allocates, setAngles() does not.
import * as THREE from 'three';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';
import { buildTree, facetPoses, foldedVertices } from './kinematics.js';
import { paperMaterial, NONE, MOUNTAIN, VALLEY, OTHER, BOUNDARY, KIND } from './paper_material.js';

const HIGHLIGHT = [1, 0.12, 0.12]; // vertex colour of colliding facets (multiplies the side colour)
const WHITE = [1, 1, 1];
const NO_LINE = -1, BOUNDARY_EDGE = -2; // what a triangle edge carries, besides a joint index
const now = () => (typeof performance !== 'undefined' ? performance.now() : Date.now());

// Whether a point lies on the segment a0–a1 (kinematics.js's sideOf() tolerance).
function crease(a0, a1) {
  const ux = a1[0] - a0[0], uy = a1[1] - a0[1], length = Math.hypot(ux, uy), tol = 1e-9 * length;
  return (p) => {
    const x = p[0] - a0[0], y = p[1] - a0[1], along = (ux * x + uy * y) / length;
    return Math.abs(ux * y - uy * x) / length <= tol && along >= -tol && along <= length + tol;
  };
}

/** A three.js view of one pattern, folded by setAngles(); draws only when something changed. */
// Multisampling on a GPU, none on a CPU rasteriser (SwiftShader, llvmpipe: headless chromium, a
// machine without a GPU), where it cost a 40 × 40 Miura-ori a sixth of its frame rate (35.6 → 29.8
// frames/s, web/bench/render.mjs). Screenshots render first, so the drawing buffer need not be kept.
function makeRenderer() {
  const renderer = new THREE.WebGLRenderer({ antialias: true });
  const gl = renderer.getContext();
  const info = gl.getExtension('WEBGL_debug_renderer_info');
  const name = info ? String(gl.getParameter(info.UNMASKED_RENDERER_WEBGL)) : '';
  if (!/swiftshader|llvmpipe|software/i.test(name)) return renderer;
  renderer.dispose();
  renderer.forceContextLoss();
  return new THREE.WebGLRenderer({ antialias: false });
}

export class View3D {
  /**
   * @param {HTMLElement} container the canvas fills it and follows its size
   * @param {{background?: number|string, colourBySign?: boolean}} [options] clear colour (default
   *   blue-grey, against which the paper-white facets stand out); colourBySign: the initial value of the colourBySign property
   */
  constructor(container, { background = 0xd9dee5, colourBySign = false } = {}) {
    this.container = container;
    this._colourBySign = colourBySign;
    this._disposed = false;
    this.renderer = makeRenderer();
    this.renderer.setPixelRatio(Math.min(globalThis.devicePixelRatio || 1, 2));
    this.renderer.setClearColor(new THREE.Color(background));
    container.appendChild(this.renderer.domElement);

    this.scene = new THREE.Scene();
    this.camera = new THREE.PerspectiveCamera(40, 1, 0.01, 1000);
    this.camera.up.set(0, 0, 1);
    this.scene.add(this.camera);
    const sky = new THREE.HemisphereLight(0xffffff, 0x606060, 1.6);
    sky.position.set(0, 0, 1); // the hemisphere's "up" is the sheet's normal
    this.scene.add(sky);
    // A head light, riding with the camera: whichever side faces the viewer is lit.
    const head = new THREE.DirectionalLight(0xffffff, 1.6);
    head.position.set(0.4, 0.8, 1);
    head.target.position.set(0, 0, -1);
    this.camera.add(head, head.target);

    this.controls = new OrbitControls(this.camera, this.renderer.domElement);
    this.controls.addEventListener('change', () => this.requestRender());

    this._frame = 0; // pending requestAnimationFrame id, 0 when none
    this._dirty = false;
    this._stats = { triangles: 0, creases: 0, lastSetAnglesMs: 0, lastRenderMs: 0 };
    this._pattern = null;
    this._overlays = new THREE.Group(); // contact points and displacement lines
    this._contacts = new THREE.Group();
    this._overlays.add(this._contacts);
    this.scene.add(this._overlays);
    // Contact points: one unit ball, scaled per point; drawn over everything (no depth test)
    // because a contact sits between facets that hide it.
    this._ball = new THREE.SphereGeometry(1, 12, 8);
    this._ballMaterial = new THREE.MeshBasicMaterial({ color: 0xff00ff, depthTest: false });
    this._resize = new ResizeObserver(() => this._fitCanvas());
    this._resize.observe(container);
    this._fitCanvas();
  }

  /**
   * Shows a pattern, flat, and frames it.
   * @param {{vertices: number[][], actors: {id: number, triangles: number[][]}[],
   *          joints: {id: number, v: number[], actors: number[], assignment?: string}[]}} pattern
   */
  setPattern(pattern) {
    this.clearHighlight();
    this.clearDisplacements();
    this._disposeSheet();
    // Counter-clockwise triangles (seen from +z) so that a computed normal is the front's.
    const V = pattern.vertices;
    const ccw = ([i, j, k]) => {
      const [a, b, c] = [V[i], V[j], V[k]];
      return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]) < 0 ? [i, k, j] : [i, j, k];
    };
    const p = { vertices: V, joints: pattern.joints, actors: pattern.actors.map((a) => ({ id: a.id, triangles: a.triangles.map(ccw) })) };
    const triangles = p.actors.reduce((s, a) => s + a.triangles.length, 0);
    this._pattern = p;
    this._tree = buildTree(p);
    this._poses = new Float64Array(16 * p.actors.length);
    this._angles = new Float64Array(p.joints.length);
    this._actorOfTriangle = new Int32Array(triangles);
    this._firstTriangle = new Int32Array(p.actors.length + 1); // actor a: triangles [first[a], first[a + 1])
    for (let a = 0, t = 0; a < p.actors.length; ++a) {
      this._firstTriangle[a] = t;
      for (const _ of p.actors[a].triangles) this._actorOfTriangle[t++] = a;
    }
    this._firstTriangle[p.actors.length] = triangles;

    // Which line each triangle edge carries (slot 3t + k: the edge opposite corner k): a joint
    // index, BOUNDARY_EDGE (an edge of one triangle only) or NO_LINE. A joint's crease may span
    // several mesh edges: an edge is on it when both its ends lie on the crease segment.
    this._edgeLine = new Int32Array(3 * triangles).fill(NO_LINE);
    const uses = new Map(); // mesh edge → {count: triangles using it, slot: the first one's}
    let t = 0;
    for (const a of p.actors)
      for (const tri of a.triangles) {
        for (let k = 0; k < 3; ++k) {
          const i = tri[(k + 1) % 3], j = tri[(k + 2) % 3], key = Math.min(i, j) * V.length + Math.max(i, j);
          const use = uses.get(key);
          if (use) use.count++;
          else uses.set(key, { count: 1, slot: 3 * t + k });
        }
        ++t;
      }
    for (const { count, slot } of uses.values()) if (count === 1) this._edgeLine[slot] = BOUNDARY_EDGE;
    p.joints.forEach((j, index) => {
      const onCrease = crease(V[j.v[0]], V[j.v[1]]);
      for (const a of j.actors)
        for (let t = this._firstTriangle[a]; t < this._firstTriangle[a + 1]; ++t) {
          const tri = p.actors[a].triangles[t - this._firstTriangle[a]];
          for (let k = 0; k < 3; ++k)
            if (onCrease(V[tri[(k + 1) % 3]]) && onCrease(V[tri[(k + 2) % 3]])) this._edgeLine[3 * t + k] = index;
        }
    });

    // One non-indexed geometry for every facet: flat normals and per-triangle line kinds need
    // unshared corners.
    const dynamic = (n, size) => new THREE.BufferAttribute(new Float32Array(n * size), size).setUsage(THREE.DynamicDrawUsage);
    this._sheet = new THREE.BufferGeometry();
    this._sheet.setAttribute('position', dynamic(3 * triangles, 3));
    this._sheet.setAttribute('normal', dynamic(3 * triangles, 3));
    this._sheet.setAttribute('color', new THREE.BufferAttribute(new Float32Array(9 * triangles).fill(1), 3));
    const bary = new Float32Array(9 * triangles);
    for (let o = 0; o < bary.length; o += 9) bary[o] = bary[o + 4] = bary[o + 8] = 1;
    this._sheet.setAttribute('bary', new THREE.BufferAttribute(bary, 3));
    this._sheet.setAttribute('edgeKind', dynamic(3 * triangles, 3));
    this._paper = new THREE.Mesh(this._sheet, paperMaterial());
    this._paper.frustumCulled = false; // folding moves the sheet out of any bounding sphere computed once
    this.scene.add(this._paper);

    this._stats.triangles = triangles;
    this._stats.creases = p.joints.length;
    this._highlighted = new Set();
    this._colourCreases();
    this.setAngles(this._angles);
    this.fit({ reset: true });
  }

  /** The angles the view shows (radians, one per joint in the pattern's joint order): a copy. */
  angles() {
    return this._angles ? Float64Array.from(this._angles) : new Float64Array(0);
  }

  /**
   * Folds the sheet: recomputes the facet poses and rewrites every position in place.
   * @param {ArrayLike<number>} angles radians, one per joint in the pattern's joint order
   */
  setAngles(angles) {
    const p = this._pattern;
    if (!p) return;
    if (angles.length !== p.joints.length) throw new RangeError(`setAngles: ${angles.length} angles for ${p.joints.length} joints`);
    const start = now();
    if (angles !== this._angles) this._angles.set(angles);
    const poses = facetPoses(p, this._tree, this._angles, this._poses);
    const position = this._sheet.attributes.position, normal = this._sheet.attributes.normal;
    const X = foldedVertices(p, poses, position.array), N = normal.array;
    for (let o = 0; o < X.length; o += 9) { // flat normal: (b - a) × (c - a), on all three corners
      const ux = X[o + 3] - X[o], uy = X[o + 4] - X[o + 1], uz = X[o + 5] - X[o + 2];
      const vx = X[o + 6] - X[o], vy = X[o + 7] - X[o + 1], vz = X[o + 8] - X[o + 2];
      let nx = uy * vz - uz * vy, ny = uz * vx - ux * vz, nz = ux * vy - uy * vx;
      const length = Math.hypot(nx, ny, nz) || 1;
      nx /= length; ny /= length; nz /= length;
      for (let k = 0; k < 9; k += 3) { N[o + k] = nx; N[o + k + 1] = ny; N[o + k + 2] = nz; }
    }
    position.needsUpdate = normal.needsUpdate = true;
    if (this._colourBySign) this._colourCreases();
    if (this._displacements) this._drawDisplacements();
    this._stats.lastSetAnglesMs = now() - start;
    this.requestRender();
  }

  /** Whether creases show the sign of their current angle (true: positive = mountain red,
   * negative = valley blue, exactly 0 by assignment) or their assignment (false, the default). */
  get colourBySign() { return this._colourBySign; }
  set colourBySign(on) {
    this._colourBySign = !!on;
    if (this._pattern) this._colourCreases();
    this.requestRender();
  }

  /**
   * Marks a collision: the actors' facets turn red, the points (folded world coordinates) show
   * as small spheres. Replaces any earlier highlight.
   * @param {{actors?: number[], points?: number[][]}} what actor indices; [x, y, z] points
   */
  highlight({ actors = [], points = [] } = {}) {
    this.clearHighlight();
    if (!this._pattern) return;
    this._highlighted = new Set(actors);
    this._paintFacets();
    const radius = 0.006 * this._diagonal();
    for (const [x, y, z] of points) {
      const m = new THREE.Mesh(this._ball, this._ballMaterial);
      m.position.set(x, y, z);
      m.scale.setScalar(radius);
      m.renderOrder = 1;
      this._contacts.add(m);
    }
    this.requestRender();
  }

  /** Removes the highlight(): facets back to paper colours, no contact points. */
  clearHighlight() {
    this._contacts.clear();
    if (this._pattern && this._highlighted?.size) {
      this._highlighted.clear();
      this._paintFacets();
    }
    this.requestRender();
  }

  /**
   * Draws a displacement per actor as a line from its folded centroid to centroid + scale·d,
   * kept up to date by setAngles(). Replaces any earlier list.
   * @param {{actor: number, dx: number, dy: number, dz: number}[]} list actor indices
   * @param {number} [scale=1] drawing scale of the displacements
   */
  showDisplacements(list, scale = 1) {
    this.clearDisplacements();
    if (!this._pattern) return;
    const geometry = new THREE.BufferGeometry();
    geometry.setAttribute('position', new THREE.BufferAttribute(new Float32Array(6 * list.length), 3));
    const lines = new THREE.LineSegments(geometry, new THREE.LineBasicMaterial({ color: 0xff8800, depthTest: false }));
    lines.frustumCulled = false;
    lines.renderOrder = 1;
    this._displacements = { list, scale, lines };
    this._overlays.add(lines);
    this._drawDisplacements();
    this.requestRender();
  }

  /** Removes the displacement lines. */
  clearDisplacements() {
    if (!this._displacements) return;
    const { lines } = this._displacements;
    this._overlays.remove(lines);
    lines.geometry.dispose();
    lines.material.dispose();
    this._displacements = null;
    this.requestRender();
  }

  /** Asks for one render at the next animation frame (any number of calls, one render). */
  requestRender() {
    this._dirty = true;
    if (this._frame || this._disposed) return;
    this._frame = requestAnimationFrame(() => {
      this._frame = 0;
      if (this._dirty) this.render();
    });
  }

  /** Renders now (the scheduled render calls this; so do screenshot() and measureFps()). */
  render() {
    const start = now();
    this.renderer.render(this.scene, this.camera);
    this._dirty = false;
    this._stats.lastRenderMs = now() - start;
  }

  /** The view as it is now. @returns {string} a PNG data URL */
  screenshot() {
    this.render();
    return this.renderer.domElement.toDataURL('image/png');
  }

  /**
   * Frames the sheet as folded now: the camera keeps its direction (from the front, above the
   * sheet, on the first call or with reset) and backs off until the whole sheet is in view.
   * @param {{reset?: boolean}} [options]
   */
  fit({ reset = false } = {}) {
    if (!this._pattern) return;
    this._sheet.computeBoundingSphere();
    const { center, radius } = this._sheet.boundingSphere;
    const direction = this.camera.position.clone().sub(this.controls.target);
    if (reset || direction.lengthSq() === 0) direction.set(0, -0.9, 1);
    const fov = THREE.MathUtils.degToRad(this.camera.fov), aspect = Math.min(this.camera.aspect, 1);
    const distance = (1.1 * radius) / Math.sin(Math.atan(Math.tan(fov / 2) * aspect)); // fits width too when narrow
    this.camera.position.copy(center).addScaledVector(direction.normalize(), distance);
    this.camera.near = distance / 100;
    this.camera.far = distance * 100;
    this.camera.updateProjectionMatrix();
    this.controls.target.copy(center);
    this.controls.update();
    this.requestRender();
  }

  /**
   * Animates setAngles(anglesAt(t)) + render() on every animation frame for `seconds`.
   * @param {number} seconds how long to run
   * @param {(t: number) => ArrayLike<number>} anglesAt angles at t seconds from the start
   * @returns {Promise<{fps: number, frames: number}>} frames drawn per second of wall time
   */
  measureFps(seconds, anglesAt) {
    return new Promise((resolve, reject) => {
      let frames = 0, start = null;
      const step = (time) => {
        try {
          if (start === null) start = time;
          const t = (time - start) / 1000;
          if (t >= seconds && frames > 0) return resolve({ fps: frames / t, frames });
          this.setAngles(anglesAt(t));
          this.render();
          frames++;
          requestAnimationFrame(step);
        } catch (error) {
          reject(error);
        }
      };
      requestAnimationFrame(step);
    });
  }

  /** Sizes, the last frame's costs and what is highlighted (facets, contact points).
   * @returns {{triangles: number, creases: number, lastSetAnglesMs: number, lastRenderMs: number, highlighted: number, contacts: number, minZ: number, maxZ: number, displacements: number}} */
  stats() {
    let minZ = Infinity, maxZ = -Infinity;
    const position = this._sheet ? this._sheet.getAttribute('position') : null;
    for (let k = 2; position && k < position.array.length; k += 3) {
      minZ = Math.min(minZ, position.array[k]);
      maxZ = Math.max(maxZ, position.array[k]);
    }
    return { ...this._stats, highlighted: this._highlighted ? this._highlighted.size : 0, contacts: this._contacts.children.length, minZ, maxZ,
      displacements: this._displacements ? this._displacements.list.length : 0 };
  }

  /** Frees the GPU resources, stops observing the container and removes the canvas. */
  dispose() {
    this._resize.disconnect();
    this.clearHighlight();
    this.clearDisplacements();
    this._disposeSheet();
    this._ball.dispose();
    this._ballMaterial.dispose();
    this.controls.dispose();
    this.renderer.dispose();
    this.renderer.domElement.remove();
    this._disposed = true; // after the clean-up above, which asks for renders
    if (this._frame) cancelAnimationFrame(this._frame);
    this._frame = 0;
  }

  // --- internals ---

  _fitCanvas() {
    const width = Math.max(1, this.container.clientWidth), height = Math.max(1, this.container.clientHeight);
    this.renderer.setSize(width, height);
    this.camera.aspect = width / height;
    this.camera.updateProjectionMatrix();
    this.requestRender();
  }

  _disposeSheet() {
    if (!this._paper) return;
    this.scene.remove(this._paper);
    this._paper.material.dispose();
    this._sheet.dispose();
    this._paper = this._sheet = this._pattern = null;
  }

  // Line kinds of every triangle edge: creases by assignment, or by the sign of their angle.
  _colourCreases() {
    const attribute = this._sheet.attributes.edgeKind, K = attribute.array, E = this._edgeLine;
    const joints = this._pattern.joints, angles = this._angles, bySign = this._colourBySign;
    for (let s = 0; s < E.length; ++s) {
      const j = E[s];
      let kind = NONE;
      if (j === BOUNDARY_EDGE) kind = BOUNDARY;
      else if (j >= 0) {
        const a = angles[j];
        kind = bySign && a > 0 ? MOUNTAIN : bySign && a < 0 ? VALLEY : KIND[joints[j].assignment] ?? OTHER;
      }
      const o = 9 * Math.floor(s / 3) + (s % 3); // component s % 3 of the triangle's three corners
      K[o] = K[o + 3] = K[o + 6] = kind;
    }
    attribute.needsUpdate = true;
  }

  _paintFacets() {
    const colour = this._sheet.attributes.color, c = colour.array;
    for (let t = 0; t < this._actorOfTriangle.length; ++t) {
      const rgb = this._highlighted.has(this._actorOfTriangle[t]) ? HIGHLIGHT : WHITE;
      for (let k = 0; k < 9; k += 3) { c[9 * t + k] = rgb[0]; c[9 * t + k + 1] = rgb[1]; c[9 * t + k + 2] = rgb[2]; }
    }
    colour.needsUpdate = true;
  }

  // Centroid of actor a's folded corners (a plain mean: enough to anchor an arrow).
  _centroid(a, out) {
    const X = this._sheet.attributes.position.array, from = 9 * this._firstTriangle[a], to = 9 * this._firstTriangle[a + 1];
    out.set(0, 0, 0);
    for (let o = from; o < to; o += 3) { out.x += X[o]; out.y += X[o + 1]; out.z += X[o + 2]; }
    return out.divideScalar((to - from) / 3);
  }

  _drawDisplacements() {
    const { list, scale, lines } = this._displacements, position = lines.geometry.attributes.position, L = position.array;
    const c = (this._centroidScratch ??= new THREE.Vector3());
    list.forEach(({ actor, dx, dy, dz }, i) => {
      this._centroid(actor, c);
      L[6 * i] = c.x; L[6 * i + 1] = c.y; L[6 * i + 2] = c.z;
      L[6 * i + 3] = c.x + scale * dx; L[6 * i + 4] = c.y + scale * dy; L[6 * i + 5] = c.z + scale * dz;
    });
    position.needsUpdate = true;
  }

  _diagonal() {
    let lo = [Infinity, Infinity], hi = [-Infinity, -Infinity];
    for (const [x, y] of this._pattern.vertices) {
      lo = [Math.min(lo[0], x), Math.min(lo[1], y)];
      hi = [Math.max(hi[0], x), Math.max(hi[1], y)];
    }
    return Math.hypot(hi[0] - lo[0], hi[1] - lo[1]) || 1;
  }
}
