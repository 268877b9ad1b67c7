// What a browser request carries over to the upstream call: the bearer token and the deadline.
import type { IncomingMessage } from "node:http";
import * as grpc from "@grpc/grpc-js";

const GRPC_TIMEOUT_UNITS: Record<string, number> = { H: 3600e3, M: 60e3, S: 1e3, m: 1, u: 1e-3, n: 1e-6 };

// gRPC's own header format ("5S", "250m"), so a gRPC-aware client can pass it unchanged.
export function parseGrpcTimeout(value: string): number {
  const match = /^(\d{1,8})([HMSmun])$/.exec(value);
  if (match === null) throw new Error(`grpc-timeout: expected digits and a unit H/M/S/m/u/n, got '${value}'`);
  return Number(match[1]) * GRPC_TIMEOUT_UNITS[match[2]];
}

export interface CallSettings {
  metadata: grpc.Metadata;
  deadlineMs?: number;   // undefined: no deadline (streams)
}

// The Authorization header (or access_token query parameter, for EventSource, which cannot set
// headers) is forwarded; the deadline comes from grpc-timeout or timeout_ms, else `fallbackMs`.
export function callSettings(request: IncomingMessage, url: URL, fallbackMs: number | undefined,
                             upstreamToken: string | undefined): CallSettings {
  const metadata = new grpc.Metadata();
  const queryToken = url.searchParams.get("access_token");
  const authorization = request.headers.authorization ??
    (queryToken !== null ? `Bearer ${queryToken}` : upstreamToken !== undefined ? `Bearer ${upstreamToken}` : undefined);
  if (authorization !== undefined) metadata.set("authorization", authorization);
  const header = request.headers["grpc-timeout"];
  const query = url.searchParams.get("timeout_ms");
  let deadlineMs = fallbackMs;
  if (typeof header === "string") deadlineMs = parseGrpcTimeout(header);
  if (query !== null) {
    deadlineMs = Number(query);
    if (!Number.isFinite(deadlineMs) || deadlineMs <= 0) throw new Error(`timeout_ms: expected milliseconds > 0, got '${query}'`);
  }
  return { metadata, deadlineMs };
}

export function grpcCallOptions(settings: CallSettings): grpc.CallOptions {
  return settings.deadlineMs === undefined ? {} : { deadline: new Date(Date.now() + settings.deadlineMs) };
}
