// The operator flow of the Flutter app against the real gateway: an instruction becomes a task,
// a robot on its session stream executes the commands, WatchTask follows the task to its end and
// the event log tells the same story.
import { after, before, test } from 'node:test';
import * as assert from 'node:assert/strict';
import * as grpc from '@grpc/grpc-js';
import { StreamReader, unary } from './support/calls';
import { serviceClient } from './support/protos';
import { ScriptedRobot } from './support/robot';
import { ServiceProcess, startService } from './support/service_process';

let gateway: ServiceProcess;
let operator: grpc.Client;
before(async () => {
  gateway = await startService('semnav-gateway');
  operator = serviceClient('semnav.reasoning.v1.OperatorService', gateway.address);
});
after(async () => {
  operator.close();
  assert.equal(await gateway.stop(), 0, 'the gateway exits 0 on SIGTERM');
});

test('instruction -> task -> robot commands -> watched to SUCCEEDED -> events', async () => {
  const robot = await ScriptedRobot.connect(gateway.address, 'r1');
  const submitted = await unary(operator, 'SubmitInstruction',
                                { request_id: 'node-req-1', robot_id: 'r1', instruction: 'look around, then wait' });
  const taskId: string = submitted.task_id;
  assert.match(taskId, /.+/);
  assert.equal(submitted.task.task_id, taskId);
  assert.deepEqual(submitted.task.subgoals.map((s: any) => s.type), ['SUBGOAL_TYPE_LOOK_AROUND', 'SUBGOAL_TYPE_WAIT']);

  // Watching from revision 0 starts with the current snapshot, so nothing is missed. The robot
  // answers only after that first snapshot arrived: otherwise the task can end before the watch
  // reaches the gateway, and the watch then rightly sees only the final snapshot.
  const watch = new StreamReader((operator as any).WatchTask({ task_id: taskId, since_revision: 0 }));
  const opening = (await watch.next()).task;
  assert.notEqual(opening.status, 'TASK_STATUS_SUCCEEDED');

  const rotate = await robot.nextCommand();
  assert.equal(rotate.action, 'rotate');
  assert.equal(rotate.task_id, taskId);
  assert.equal(rotate.rotate.duration_s, 12);
  robot.report(rotate, 'FEEDBACK_KIND_GOAL_REACHED');
  const hold = await robot.nextCommand();
  assert.equal(hold.action, 'hold');
  assert.equal(hold.hold.duration_s, 5);
  robot.report(hold, 'FEEDBACK_KIND_GOAL_REACHED');
  assert.equal((await robot.nextCommand()).action, 'stop');

  const { messages, status } = await watch.drain();
  assert.equal(status.code, grpc.status.OK, 'WatchTask ends OK when the task finishes');
  const snapshots = [opening, ...messages.map((m: any) => m.task)];
  assert.ok(snapshots.length >= 2, `snapshots: ${snapshots.length}`);
  for (let i = 1; i < snapshots.length; ++i) assert.ok(snapshots[i].revision > snapshots[i - 1].revision);
  const last = snapshots[snapshots.length - 1];
  assert.equal(last.status, 'TASK_STATUS_SUCCEEDED');
  assert.equal(last.progress, 1);
  assert.equal(last.current_subgoal, 2);
  assert.equal((await unary(operator, 'GetTask', { task_id: taskId })).task.revision, last.revision);

  // Replay of the log after event 1 (the session opening): the task's whole story, ids increasing.
  const events = new StreamReader((operator as any).StreamEvents({ robot_id: 'r1', last_event_id: 1 }));
  const story: any[] = [];
  while (story.length === 0 || story[story.length - 1].kind !== 'EVENT_KIND_TASK_STATUS') {
    story.push((await events.next()).event);
  }
  events.cancel();
  story.forEach((event, i) => assert.ok(event.event_id > (i === 0 ? 1 : story[i - 1].event_id)));
  assert.ok(story.every((event) => event.robot_id === 'r1'));
  assert.deepEqual(story[0].kind, 'EVENT_KIND_TASK_CREATED');
  assert.ok(story.some((event) => event.kind === 'EVENT_KIND_SUBGOAL' && event.task_id === taskId));
  assert.equal(story[story.length - 1].task_id, taskId);
  assert.match(story[story.length - 1].message, /^TASK_STATUS_SUCCEEDED/);

  // Same request_id again: the first answer, no second task.
  const repeated = await unary(operator, 'SubmitInstruction',
                               { request_id: 'node-req-1', robot_id: 'r1', instruction: 'look around, then wait' });
  assert.equal(repeated.task_id, taskId);
  await robot.leave();
});
