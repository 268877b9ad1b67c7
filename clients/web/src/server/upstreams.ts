// The upstream gRPC services, their methods read from the .proto files at start-up, and one
// channel per service (plaintext, TLS or mTLS).
import * as fs from "node:fs";
import * as grpc from "@grpc/grpc-js";
import * as protoLoader from "@grpc/proto-loader";
import type { ProxyConfig } from "./config";

// URL name -> fully qualified service and the proto file defining it.
export const SERVICES = {
  operator: { service: "semnav.reasoning.v1.OperatorService", file: "semnav/reasoning/v1/operator.proto" },
  mapping: { service: "semnav.mapping.v1.MappingService", file: "semnav/mapping/v1/mapping_service.proto" },
  planning: { service: "semnav.planning.v1.PlanningService", file: "semnav/planning/v1/planning_service.proto" },
} as const;
export type ServiceName = keyof typeof SERVICES;

// JSON shape: proto field names as written (snake_case), enums as names, 64-bit integers as
// strings, bytes as base64, every field present, the set member of a oneof named.
export const JSON_OPTIONS: protoLoader.Options = {
  keepCase: true,
  longs: String,
  enums: String,
  bytes: String,
  defaults: true,
  oneofs: true,
};

export interface Upstream {
  client: grpc.Client;
  methods: Record<string, protoLoader.MethodDefinition<object, object>>;
}

export function loadPackages(protoDir: string): protoLoader.PackageDefinition {
  return protoLoader.loadSync(
    Object.values(SERVICES).map((s) => s.file),
    { ...JSON_OPTIONS, includeDirs: [protoDir] },
  );
}

function credentials(config: ProxyConfig): grpc.ChannelCredentials {
  const tls = config.tls;
  if (tls.caFile === undefined && tls.certFile === undefined) return grpc.credentials.createInsecure();
  const read = (file?: string) => (file === undefined ? null : fs.readFileSync(file));
  return grpc.credentials.createSsl(read(tls.caFile), read(tls.keyFile), read(tls.certFile));
}

export function connectUpstreams(config: ProxyConfig, packages: protoLoader.PackageDefinition): Record<ServiceName, Upstream> {
  const creds = credentials(config);
  const options: grpc.ChannelOptions = {};
  if (config.tls.serverName !== undefined) options["grpc.ssl_target_name_override"] = config.tls.serverName;
  const address: Record<ServiceName, string> = {
    operator: config.gateway,
    mapping: config.mapping,
    planning: config.planning,
  };
  const result = {} as Record<ServiceName, Upstream>;
  for (const name of Object.keys(SERVICES) as ServiceName[]) {
    const methods = packages[SERVICES[name].service] as unknown as Upstream["methods"];
    if (methods === undefined) throw new Error(`${SERVICES[name].service} not found in the protos`);
    const Client = grpc.makeGenericClientConstructor(methods, SERVICES[name].service);
    result[name] = { client: new Client(address[name], creds, options), methods };
  }
  return result;
}
