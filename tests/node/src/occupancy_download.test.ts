// GetOccupancy: the OctoMap of a box as DataChunks. The client reassembles them by offset,
// checks size and SHA-256, and reads the .bt file: the wall and the chair of the frame are there.
import { after, before, test } from 'node:test';
import * as assert from 'node:assert/strict';
import { createHash } from 'node:crypto';
import { StreamReader } from './support/calls';
import { wallFrame } from './support/frames';
import { MappingUnderTest, startMapping, streamFrames } from './support/mapping';
import { parseOctomapBt } from './support/octomap_bt';

let mapping: MappingUnderTest;
before(async () => {
  // Small chunks so the 12 KB test map crosses several chunk boundaries.
  mapping = await startMapping('  occupancy_chunk_bytes: 4096\n');
  await streamFrames(mapping.client, [wallFrame(1)]);
});
after(async () => {
  await mapping.stop();
});

// Concatenates the chunks, checking the DataChunk rules on the way.
async function download(request: object): Promise<{ payload: Buffer; contentType: string; chunks: number }> {
  const { messages, status } = await new StreamReader((mapping.client as any).GetOccupancy(request)).drain();
  assert.equal(status.code, 0, status.details);
  assert.ok(messages.length >= 1);
  const parts: Buffer[] = [];
  let received = 0;
  const totalSize = messages[0].chunk.total_size;
  messages.forEach(({ chunk }, index) => {
    assert.equal(chunk.offset, received, `chunk ${index} offset`);
    assert.equal(chunk.total_size, totalSize, `chunk ${index} total_size`);
    assert.ok(chunk.data.length <= 1 << 20, `chunk ${index} exceeds 1 MiB`);
    assert.equal(chunk.content_type !== '', index === 0, `content_type only on the first chunk`);
    assert.equal(chunk.sha256 !== '', index === messages.length - 1, `sha256 only on the last chunk`);
    parts.push(chunk.data);
    received += chunk.data.length;
  });
  const payload = Buffer.concat(parts);
  assert.equal(payload.length, totalSize);
  assert.equal(messages[messages.length - 1].chunk.sha256, createHash('sha256').update(payload).digest('hex'));
  return { payload, contentType: messages[0].chunk.content_type, chunks: messages.length };
}

test('chunks reassemble into a checksummed OctoMap holding the wall and the chair', async () => {
  const { payload, contentType, chunks } = await download({ min: { x: 0, y: -1, z: -1 }, max: { x: 4, y: 5, z: 3 } });
  assert.equal(chunks, Math.ceil(payload.length / 4096), `chunks for ${payload.length} bytes`);
  assert.ok(chunks >= 2, `expected several chunks, got ${chunks}`);
  assert.equal(contentType, 'application/x-octomap-bt');
  const tree = parseOctomapBt(payload);
  assert.equal(tree.id, 'OcTree');
  assert.equal(tree.resolution, 0.05);
  // Depth 3 m (wall) and 2 m (chair) from a camera at x = 0.5 looking along +x.
  const wall = tree.occupied.filter(([x]) => x > 3.45 && x < 3.6);
  const chair = tree.occupied.filter(([x]) => x > 2.45 && x < 2.6);
  assert.ok(wall.length > 500, `wall voxels: ${wall.length}`);
  assert.ok(chair.length > 50, `chair voxels: ${chair.length}`);
  assert.equal(wall.length + chair.length, tree.occupied.length, 'occupied voxels only at the two depths');
  // The 40 x 40 pixel box at 2 m with f = 100 px is 0.8 m square around (2.5, 2, 1).
  for (const [x, y, z] of chair) {
    assert.ok(Math.abs(y - 2.0) < 0.45 && Math.abs(z - 1.0) < 0.45, `chair voxel at ${x}, ${y}, ${z}`);
  }
  assert.ok(tree.free.some(([x, y, z]) => x > 1 && x < 2 && Math.abs(y - 2) < 0.1 && Math.abs(z - 1) < 0.1),
            'free space between the camera and the chair');
});

test('a box outside the map downloads as an empty tree', async () => {
  const { payload } = await download({ min: { x: 20, y: 20, z: 0 }, max: { x: 21, y: 21, z: 1 } });
  const tree = parseOctomapBt(payload);
  assert.equal(tree.occupied.length + tree.free.length, 0);
  assert.equal(tree.resolution, 0.05);
});
