// A robot scripted by the test on RobotSessionService.Connect: hello, pose, then one command at a
// time with feedback, as clients/sim/loop/robot_session does for the simulator.
import * as grpc from '@grpc/grpc-js';
import { StreamReader } from './calls';
import { serviceClient } from './protos';

export class ScriptedRobot {
  private constructor(
    private readonly client: grpc.Client,
    private readonly stream: grpc.ClientDuplexStream<object, any>,
    private readonly reader: StreamReader,
    readonly sessionId: string,
  ) {}

  static async connect(address: string, robotId: string): Promise<ScriptedRobot> {
    const client = serviceClient('semnav.reasoning.v1.RobotSessionService', address);
    const stream: grpc.ClientDuplexStream<object, any> = (client as any).Connect();
    const reader = new StreamReader(stream);
    stream.write({ hello: { robot_id: robotId, capabilities: { modes: ['LOCOMOTION_MODE_GROUND'] } } });
    const first = await reader.next();
    if (first.body !== 'accepted') throw new Error(`expected SessionAccepted, got ${first.body}`);
    const robot = new ScriptedRobot(client, stream, reader, first.accepted.session_id);
    robot.reportPose(0, 0);
    return robot;
  }

  reportPose(x: number, y: number): void {
    this.stream.write({ state: { pose: { position: { x, y, z: 0 }, orientation: { w: 1 } } } });
  }

  async nextCommand(): Promise<any> {
    const response = await this.reader.next();
    if (response.body !== 'command') throw new Error(`expected a command, got ${response.body}`);
    return response.command;
  }

  report(command: any, kind: string): void {
    this.stream.write({ feedback: { command_id: command.command_id, kind } });
  }

  async leave(): Promise<void> {
    this.stream.end();
    await this.reader.drain();
    this.client.close();
  }
}
