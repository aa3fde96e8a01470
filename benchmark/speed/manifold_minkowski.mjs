// Times Manifold's minkowskiSum (npm manifold-3d) on two OFF triangle meshes.
//   node manifold_minkowski.mjs P.off Q.off [scale_q]   -> one JSON line on stdout (seconds, area of the sum)
import fs from 'node:fs';
import Module from 'manifold-3d';

function readOff(path, scale) {
  const tok = fs.readFileSync(path, 'utf8').split(/\s+/).filter((t) => t.length && !t.startsWith('#'));
  if (tok[0] !== 'OFF') throw new Error(`${path}: not an OFF file`);
  const nv = +tok[1], nf = +tok[2];
  let i = 4;
  const vert = new Float32Array(3 * nv);
  for (let k = 0; k < 3 * nv; ++k) vert[k] = +tok[i++] * scale;
  const tris = [];
  for (let f = 0; f < nf; ++f) {
    const n = +tok[i++];
    const poly = [];
    for (let k = 0; k < n; ++k) poly.push(+tok[i++]);
    for (let k = 1; k + 1 < n; ++k) tris.push(poly[0], poly[k], poly[k + 1]);
  }
  return { numProp: 3, vertProperties: vert, triVerts: new Uint32Array(tris) };
}

const [p, q, s] = process.argv.slice(2);
const wasm = await Module();
wasm.setup();
const { Manifold, Mesh } = wasm;
const load = (path, scale) => {
  const data = readOff(path, scale);
  let m = new Manifold(Object.assign(new Mesh(data), {}));
  if (m.volume() < 0) { // inward (CGAL's tetrahedron.off): reverse the triangles, as pmsum does
    const t = data.triVerts;
    for (let k = 0; k < t.length; k += 3) [t[k + 1], t[k + 2]] = [t[k + 2], t[k + 1]];
    m = new Manifold(new Mesh(data));
  }
  if (m.status() !== 'NoError') throw new Error(`${path}: ${m.status()}`);
  return m;
};
const t0 = performance.now();
const P = load(p, 1), Q = load(q, s ? +s : 1);
const t1 = performance.now();
const sum = P.minkowskiSum(Q);
const t2 = performance.now();
const area = typeof sum.surfaceArea === 'function' ? sum.surfaceArea() : null;
console.log(JSON.stringify({ seconds_load: (t1 - t0) / 1000, seconds: (t2 - t1) / 1000, triangles: sum.numTri(),
                             surface_area: area, status: sum.status() }));
