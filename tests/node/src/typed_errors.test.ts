// Typed errors as a non-C++ client decodes them: the status code, and in the
// grpc-status-details-bin trailer a RichStatus (google.rpc.Status layout) whose ErrorInfo names
// the offending request field. Unary, server-streaming and bidi calls alike; state unchanged.
import { after, before, test } from 'node:test';
import * as assert from 'node:assert/strict';
import * as grpc from '@grpc/grpc-js';
import { StreamReader, callError, unary } from './support/calls';
import { wallFrame } from './support/frames';
import { MappingUnderTest, startMapping, streamFrames } from './support/mapping';
import { serviceClient } from './support/protos';
import { TypedError, typedError } from './support/rich_status';
import { ServiceProcess, startService } from './support/service_process';

let mapping: MappingUnderTest;
let gateway: ServiceProcess;
let operator: grpc.Client;
before(async () => {
  [mapping, gateway] = await Promise.all([startMapping(), startService('semnav-gateway')]);
  operator = serviceClient('semnav.reasoning.v1.OperatorService', gateway.address);
  await streamFrames(mapping.client, [wallFrame(1)]);
});
after(async () => {
  operator.close();
  await Promise.all([mapping.stop(), gateway.stop()]);
});

function expectTyped(error: grpc.ServiceError | grpc.StatusObject, code: grpc.status, field: string, reason = 'FIELD_INVALID'): TypedError {
  const typed = typedError(error);
  assert.equal(typed.code, code, error.details);
  assert.equal(typed.detailsCode, code, 'RichStatus.code is the call status');
  assert.equal(typed.detailsMessage, error.details, 'RichStatus.message is the call message');
  assert.equal(typed.field, field);
  assert.equal(typed.reason, reason);
  return typed;
}

test('unary calls name the bad field and leave the map as it was', async () => {
  const before = JSON.stringify(await unary(mapping.client, 'GetSceneGraph', {}));
  expectTyped(await callError(unary(mapping.client, 'GetGridMap', { window: { min: { x: 2 }, max: { x: 1, y: 1 } } })),
              grpc.status.INVALID_ARGUMENT, 'window.max.x');
  expectTyped(await callError(unary(mapping.client, 'SaveMap', { map_id: 'lab' })),
              grpc.status.INVALID_ARGUMENT, 'request_id');
  expectTyped(await callError(unary(mapping.client, 'LoadMap', { request_id: 'load-1', map_id: 'never-saved' })),
              grpc.status.NOT_FOUND, 'map_id', 'NOT_FOUND');
  assert.equal(JSON.stringify(await unary(mapping.client, 'GetSceneGraph', {})), before);
});

test('a server stream fails in its trailer with the same typed detail', async () => {
  const reader = new StreamReader((mapping.client as any).GetOccupancy({ max: { x: 1, y: 1 } }));
  const error = await reader.next().then(() => assert.fail('GetOccupancy sent a chunk for a flat box'), (e) => e);
  expectTyped(error, grpc.status.INVALID_ARGUMENT, 'max.z');
});

test('the gateway names operator fields', async () => {
  expectTyped(await callError(unary(operator, 'SubmitInstruction', { robot_id: 'r1', instruction: 'look around' })),
              grpc.status.INVALID_ARGUMENT, 'request_id');
  expectTyped(await callError(unary(operator, 'GetTask', { task_id: 'no-such-task' })), grpc.status.NOT_FOUND, 'task_id', 'NOT_FOUND');
});

test('a robot session that does not start with hello is refused on field "hello"', async () => {
  const client = serviceClient('semnav.reasoning.v1.RobotSessionService', gateway.address);
  const stream = (client as any).Connect();
  const reader = new StreamReader(stream);
  stream.write({ state: { pose: { orientation: { w: 1 } } } });
  const error = await reader.next().then(() => assert.fail('the gateway answered a session without hello'), (e) => e);
  expectTyped(error, grpc.status.INVALID_ARGUMENT, 'hello');
  client.close();
});
