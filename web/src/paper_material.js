// The paper of the 3D view (view3d.js): one three.js material for both sides of the sheet, its
// creases and boundary inked by the facets' own shader, and the line kinds it draws.
import * as THREE from 'three';

const FRONT = 0xf7f5ee; // paper white: the side facing +z when flat
const BACK = 0x8193a8; // blue-grey: the other side (Origami Simulator's two-colour paper)
/** Line kinds of a triangle edge (the shader's edgeKind attribute), and a joint assignment's kind. */
export const NONE = 0, MOUNTAIN = 1, VALLEY = 2, OTHER = 3, BOUNDARY = 4;
export const KIND = Object.freeze({ M: MOUNTAIN, V: VALLEY, F: OTHER, U: OTHER });
// The ink of each line kind (THREE.Color holds linear components, what the shader mixes in before
// its colour-space conversion).
const INK = ['#000000', '#ff0000', '#0000ff', '#888888', '#000000'].map((css) => new THREE.Color(css));
const CREASE_HALF_WIDTH = 0.9, BOUNDARY_WIDTH = 1.4; // pixels (a crease is inked from both sides)

// The paper: Lambert, both sides in one draw (front colour or back colour by gl_FrontFacing), and
// the creases and boundary inked by the facets' own fragment shader rather than drawn as GL
// lines, which in headless Chromium (SwiftShader) took about as long as the sheet. Per corner,
// `bary` is the corner's barycentric unit vector and `edgeKind[k]` the line kind of the edge
// opposite corner k (equal at the three corners): vBary[k] / fwidth(vBary[k]) is the distance in
// pixels to that edge. Per-triangle work (kind → ink and width) is done in the vertex shader.
export function paperMaterial() {
  const material = new THREE.MeshLambertMaterial({ color: FRONT, side: THREE.DoubleSide, vertexColors: true });
  material.onBeforeCompile = (shader) => {
    Object.assign(shader.uniforms, {
      backColour: { value: new THREE.Color(BACK) },
      ink: { value: INK },
      creaseHalfWidth: { value: CREASE_HALF_WIDTH },
      boundaryWidth: { value: BOUNDARY_WIDTH },
    });
    const varyings = 'varying vec3 vBary;\nflat varying vec3 vLineWidth;\nflat varying mat3 vInk;';
    shader.vertexShader = shader.vertexShader
      .replace('#include <common>', `#include <common>
attribute vec3 bary;
attribute vec3 edgeKind;
uniform vec3 ink[${INK.length}];
uniform float creaseHalfWidth;
uniform float boundaryWidth;
${varyings}`)
      .replace('#include <begin_vertex>', `#include <begin_vertex>
vBary = bary;
for (int k = 0; k < 3; ++k) {
  int kind = int(edgeKind[k] + 0.5);
  vLineWidth[k] = kind == ${NONE} ? -1e9 : kind == ${BOUNDARY} ? boundaryWidth : creaseHalfWidth; // -1e9: no line
  vInk[k] = ink[kind];
}`);
    shader.fragmentShader = shader.fragmentShader
      .replace('#include <common>', `#include <common>\nuniform vec3 backColour;\n${varyings}`)
      .replace('vec4 diffuseColor = vec4( diffuse, opacity );', 'vec4 diffuseColor = vec4( gl_FrontFacing ? diffuse : backColour, opacity );')
      .replace('#include <opaque_fragment>', `#include <opaque_fragment>
{
  vec3 outside = vBary / max(fwidth(vBary), vec3(1e-6)) - vLineWidth; // pixels outside each line
  float nearest = min(outside.x, min(outside.y, outside.z));
  vec3 colour = nearest == outside.x ? vInk[0] : nearest == outside.y ? vInk[1] : vInk[2];
  gl_FragColor.rgb = mix(gl_FragColor.rgb, colour, 1.0 - smoothstep(-0.5, 0.5, nearest));
}`);
  };
  return material;
}
