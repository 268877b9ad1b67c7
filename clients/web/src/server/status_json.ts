// gRPC status -> HTTP status and a JSON error body, with the typed details the services attach
// (semnav.common.v1.RichStatus in grpc-status-details-bin: ErrorInfo, PlanFailureDetail, ...).
import * as fs from "node:fs";
import * as path from "node:path";
import * as grpc from "@grpc/grpc-js";
import * as protobuf from "protobufjs";
import { JSON_OPTIONS, SERVICES } from "./upstreams";

// google.api HTTP mapping of gRPC codes (google/rpc/code.proto).
const HTTP_STATUS: Record<number, number> = {
  [grpc.status.OK]: 200,
  [grpc.status.CANCELLED]: 499,
  [grpc.status.UNKNOWN]: 500,
  [grpc.status.INVALID_ARGUMENT]: 400,
  [grpc.status.DEADLINE_EXCEEDED]: 504,
  [grpc.status.NOT_FOUND]: 404,
  [grpc.status.ALREADY_EXISTS]: 409,
  [grpc.status.PERMISSION_DENIED]: 403,
  [grpc.status.UNAUTHENTICATED]: 401,
  [grpc.status.RESOURCE_EXHAUSTED]: 429,
  [grpc.status.FAILED_PRECONDITION]: 400,
  [grpc.status.ABORTED]: 409,
  [grpc.status.OUT_OF_RANGE]: 400,
  [grpc.status.UNIMPLEMENTED]: 501,
  [grpc.status.INTERNAL]: 500,
  [grpc.status.UNAVAILABLE]: 503,
  [grpc.status.DATA_LOSS]: 500,
};

export interface ErrorBody {
  code: string;          // gRPC code name, e.g. "FAILED_PRECONDITION"
  message: string;
  details: object[];     // each with "@type" (full message name) and its fields
}

export function httpStatus(code: grpc.status): number {
  return HTTP_STATUS[code] ?? 500;
}

export function codeName(code: grpc.status): string {
  return grpc.status[code] ?? `CODE_${code}`;
}

export class DetailDecoder {
  private readonly root = new protobuf.Root();

  constructor(protoDir: string) {
    this.root.resolvePath = (origin, target) => {
      const local = path.join(protoDir, target);
      return fs.existsSync(local) ? local : protobuf.util.path.resolve(origin, target);
    };
    this.root.loadSync(["semnav/common/v1/errors.proto", ...Object.values(SERVICES).map((s) => s.file)], { keepCase: true });
  }

  toBody(error: Partial<grpc.ServiceError>): ErrorBody {
    const code = error.code ?? grpc.status.UNKNOWN;
    return { code: codeName(code), message: error.details ?? error.message ?? "", details: this.details(error.metadata) };
  }

  private details(metadata?: grpc.Metadata): object[] {
    const raw = metadata?.get("grpc-status-details-bin")[0];
    if (!(raw instanceof Buffer)) return [];
    const conversion = JSON_OPTIONS as protobuf.IConversionOptions;  // the same JSON shape as responses
    const rich = this.root.lookupType("semnav.common.v1.RichStatus").decode(raw) as unknown as {
      details: { type_url: string; value: Uint8Array }[];
    };
    return rich.details.map((any) => {
      const typeName = any.type_url.slice(any.type_url.lastIndexOf("/") + 1);
      try {
        const type = this.root.lookupType(typeName);
        return { "@type": typeName, ...type.toObject(type.decode(any.value), conversion) };
      } catch {
        return { "@type": typeName };  // a detail type outside the loaded protos
      }
    });
  }
}
