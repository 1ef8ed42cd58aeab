// Decoding of the meshes `swept view` embeds: base64 of deflate (zlib) streams of zigzag-coded
// byte planes (the encoder is apps/swept/cmd_view.cpp, encode_mesh).

/** Base64 text to bytes. */
export function base64ToBytes(text) {
  const binary = atob(text);
  const bytes = new Uint8Array(binary.length);
  for (let i = 0; i < binary.length; i++) bytes[i] = binary.charCodeAt(i);
  return bytes;
}

/** Inflates a zlib ("deflate") stream with the browser's own DecompressionStream (no network). */
export async function inflate(bytes) {
  const stream = new Blob([bytes]).stream().pipeThrough(new DecompressionStream('deflate'));
  return new Uint8Array(await new Response(stream).arrayBuffer());
}

/**
 * Quantised vertex positions, uint16 per coordinate (x, y, z interleaved). Encoded as, per
 * coordinate, the step from the previous vertex (modulo 2^16), zigzag coded, in two byte planes
 * (all low bytes, then all high bytes).
 */
export function decodePositions(bytes, vertexCount, what) {
  const n = vertexCount * 3;
  if (bytes.length !== n * 2) throw new Error(`${what}: expected ${vertexCount} vertices, got ${bytes.length / 6}`);
  const out = new Uint16Array(n);
  const last = [0, 0, 0];
  for (let i = 0; i < n; i++) {
    const code = bytes[i] | (bytes[n + i] << 8);
    const step = (code >>> 1) ^ -(code & 1);
    const c = i % 3;
    last[c] = (last[c] + step) & 0xffff;
    out[i] = last[c];
  }
  return out;
}

/**
 * Triangle corner indices. Encoded as the distance back from the high-water mark (one past the
 * largest index so far), zigzag coded, as uint32 in four byte planes.
 */
export function decodeIndices(bytes, triangleCount, vertexCount, what) {
  const n = triangleCount * 3;
  if (bytes.length !== n * 4) throw new Error(`${what}: expected ${triangleCount} triangles, got ${bytes.length / 12}`);
  const out = new Uint32Array(n);
  let highWater = 0;
  for (let i = 0; i < n; i++) {
    const code = (bytes[i] | (bytes[n + i] << 8) | (bytes[2 * n + i] << 16) | (bytes[3 * n + i] << 24)) >>> 0;
    const back = code % 2 === 0 ? code / 2 : -(code + 1) / 2;
    const index = highWater - back;
    if (!(index >= 0 && index < vertexCount)) throw new Error(`${what}: index ${index} out of range at corner ${i}`);
    out[i] = index;
    if (index + 1 > highWater) highWater = index + 1;
  }
  return out;
}
