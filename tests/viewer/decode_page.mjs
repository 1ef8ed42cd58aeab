// Decodes the meshes of a page written by `swept view` with the viewer's own decoder
// (viewer/src/decode.js) and prints them as JSON: {"obstacles": [[x,y,z] × 3 per triangle ...],
// "body": [...]}, coordinates dequantised to the model's unit (body in the body frame).
//   node tests/viewer/decode_page.mjs VIEW.html
import { readFileSync } from 'node:fs';
import { base64ToBytes, decodeIndices, decodePositions, inflate } from '../../viewer/src/decode.js';

const file = process.argv[2];
if (!file) {
  console.error('usage: node tests/viewer/decode_page.mjs VIEW.html');
  process.exit(2);
}
const html = readFileSync(file, 'utf8');
const open = '<script id="swept-data" type="application/json">';
const begin = html.indexOf(open);
const end = html.indexOf('</script>', begin);
if (begin < 0 || end < 0) {
  console.error(`${file}: no swept-data script`);
  process.exit(1);
}
const data = JSON.parse(html.slice(begin + open.length, end));
const out = {};
for (const name of ['obstacles', 'body']) {
  const m = data.meshes[name];
  const positions = decodePositions(await inflate(base64ToBytes(m.positions)), m.vertices, `${name} positions`);
  const indices = decodeIndices(await inflate(base64ToBytes(m.indices)), m.triangles, m.vertices, `${name} indices`);
  const size = [0, 1, 2].map((a) => (m.max[a] - m.min[a] > 0 ? m.max[a] - m.min[a] : 1));
  const vertex = (i) => [0, 1, 2].map((a) => m.min[a] + (positions[3 * i + a] / 65535) * size[a]);
  const triangles = [];
  for (let t = 0; t < m.triangles; t++) triangles.push([0, 1, 2].map((k) => vertex(indices[3 * t + k])));
  out[name] = triangles;
}
console.log(JSON.stringify(out));
