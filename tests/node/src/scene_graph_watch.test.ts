// WatchSceneGraph: a snapshot first, then deltas; a client that reconnects with the revision it
// has gets only what changed after it.
import { after, before, test } from 'node:test';
import * as assert from 'node:assert/strict';
import { StreamReader, unary } from './support/calls';
import { wallFrame } from './support/frames';
import { MappingUnderTest, startMapping, streamFrames } from './support/mapping';

let mapping: MappingUnderTest;
before(async () => {
  mapping = await startMapping();
});
after(async () => {
  await mapping.stop();
});

function watch(sinceRevision: number): StreamReader {
  return new StreamReader((mapping.client as any).WatchSceneGraph({ since_revision: sinceRevision }));
}

test('snapshot, delta on new frames, and resume by revision', async () => {
  const live = watch(0);
  const first = await live.next();
  assert.equal(first.update, 'snapshot');
  assert.equal(first.snapshot.objects.length, 0);
  const empty = first.snapshot.revision;

  const acks = await streamFrames(mapping.client, [wallFrame(1)]);
  assert.equal(acks[0].accepted, true, JSON.stringify(acks[0].error));
  assert.equal(acks[0].detections_used, 1);
  const created = await live.next();
  assert.equal(created.update, 'delta');
  assert.equal(created.delta.from_revision, empty);
  assert.ok(created.delta.revision > empty);
  assert.deepEqual(created.delta.upserted_objects.map((o: any) => o.label), ['chair']);
  const chair = created.delta.upserted_objects[0];
  assert.equal(chair.observation_count, 1);
  // The box 2 m in front of the camera at (0.5, 2, 1): front face at x = 2.5.
  assert.ok(Math.abs(chair.position.x - 2.5) < 0.1 && Math.abs(chair.position.y - 2) < 0.1 &&
            Math.abs(chair.position.z - 1) < 0.1, JSON.stringify(chair.position));
  live.cancel();
  const seen = created.delta.revision;

  // While disconnected the chair is seen twice more.
  await streamFrames(mapping.client, [wallFrame(2), wallFrame(3)]);
  const now = (await unary(mapping.client, 'GetSceneGraph', {})).graph;
  assert.ok(now.revision > seen);

  const resumed = watch(seen);
  const catchUp = await resumed.next();
  assert.equal(catchUp.update, 'delta', 'resuming from a known revision must not resend a snapshot');
  assert.equal(catchUp.delta.from_revision, seen);
  assert.equal(catchUp.delta.revision, now.revision);
  assert.equal(catchUp.delta.upserted_objects.length, 1);
  assert.equal(catchUp.delta.upserted_objects[0].observation_count, 3);
  assert.equal(catchUp.delta.summary, now.summary);
  resumed.cancel();

  // From 0 it is a snapshot of the same state.
  const fresh = watch(0);
  const snapshot = await fresh.next();
  assert.equal(snapshot.update, 'snapshot');
  assert.equal(snapshot.snapshot.revision, now.revision);
  fresh.cancel();
});
