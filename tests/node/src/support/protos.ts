// The semnav schema as a non-C++ client sees it: protos/ parsed at run time by proto-loader,
// no generated code. SEMNAV_PROTO_DIR points at the repository's protos/ folder.
import * as grpc from '@grpc/grpc-js';
import * as protoLoader from '@grpc/proto-loader';
import * as protobuf from 'protobufjs';
import * as fs from 'node:fs';
import * as path from 'node:path';

export const protoDir: string = requiredEnv('SEMNAV_PROTO_DIR');

function requiredEnv(name: string): string {
  const value = process.env[name];
  if (!value) throw new Error(`${name} is not set (run through ctest: tests/node/run.sh)`);
  return value;
}

// Every .proto under protos/semnav, relative to the proto root (the import root).
function semnavProtoFiles(): string[] {
  const files: string[] = [];
  const walk = (dir: string) => {
    for (const entry of fs.readdirSync(dir, { withFileTypes: true })) {
      const full = path.join(dir, entry.name);
      if (entry.isDirectory()) walk(full);
      else if (entry.name.endsWith('.proto')) files.push(path.relative(protoDir, full));
    }
  };
  walk(path.join(protoDir, 'semnav'));
  return files.sort();
}

// Field names as written in the .proto (snake_case), enums as names, 64-bit ints as JS numbers
// (every id and revision the tests see is far below 2^53), unset fields with their defaults and
// the name of the set oneof member in the oneof's own field.
const packageDefinition = protoLoader.loadSync(semnavProtoFiles(), {
  includeDirs: [protoDir],
  keepCase: true,
  longs: Number,
  enums: String,
  defaults: true,
  oneofs: true,
});

// Service constructors are reached by their full proto names, e.g.
// serviceClient('semnav.mapping.v1.MappingService').
const loaded = grpc.loadPackageDefinition(packageDefinition);

export function serviceClient(fullName: string, address: string): grpc.Client {
  let node: any = loaded;
  for (const part of fullName.split('.')) node = node?.[part];
  if (typeof node !== 'function') throw new Error(`service ${fullName} not found in ${protoDir}`);
  return new node(address, grpc.credentials.createInsecure());
}

// Decoding of one message type by full name, for payloads that are not a call's response (the
// typed error details). protobufjs is the parser under proto-loader; same files, same options.
const root = new protobuf.Root();
root.resolvePath = (_origin, target) => (target.startsWith('google/protobuf/') ? target : path.join(protoDir, target));
root.loadSync(semnavProtoFiles(), { keepCase: true });

export function decodeMessage(fullName: string, bytes: Uint8Array): any {
  const type = root.lookupType(fullName);
  return type.toObject(type.decode(bytes), { longs: Number, enums: String, defaults: true, oneofs: true });
}
