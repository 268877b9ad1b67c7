// A real semnav-mapping with its own map store, and the frame stream a robot would feed it.
import * as fs from 'node:fs';
import * as path from 'node:path';
import * as grpc from '@grpc/grpc-js';
import { StreamReader } from './calls';
import { serviceClient } from './protos';
import { ServiceProcess, startService, tempDir } from './service_process';

export interface MappingUnderTest {
  service: ServiceProcess;
  client: grpc.Client;
  stop(): Promise<void>;
}

// `extraYaml` is appended inside the `mapping:` section (two-space indented keys).
export async function startMapping(extraYaml = ''): Promise<MappingUnderTest> {
  const dir = tempDir('mapping');
  const config = path.join(dir, 'mapping.yaml');
  fs.writeFileSync(config, `mapping:\n  store_directory: ${path.join(dir, 'maps')}\n  watch_min_interval_ms: 50\n${extraYaml}`);
  const service = await startService('semnav-mapping', ['--config', config]);
  const client = serviceClient('semnav.mapping.v1.MappingService', service.address);
  return {
    service,
    client,
    stop: async () => {
      client.close();
      await service.stop();
      fs.rmSync(dir, { recursive: true, force: true });
    },
  };
}

// Streams frames one by one (each waits for its ack, as the service answers in order) and
// returns the acks; the stream must end OK.
export async function streamFrames(client: grpc.Client, frames: object[]): Promise<any[]> {
  const stream: grpc.ClientDuplexStream<object, any> = (client as any).StreamFrames();
  const reader = new StreamReader(stream);
  const acks = [];
  for (const frame of frames) {
    stream.write({ frame });
    acks.push((await reader.next(20000)).ack);
  }
  stream.end();
  const { status } = await reader.drain();
  if (status.code !== grpc.status.OK) throw new Error(`StreamFrames ended with ${status.code}: ${status.details}`);
  return acks;
}
