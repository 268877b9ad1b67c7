// Typed errors as semnav sends them (services/common/status): a RichStatus, wire-compatible with
// google.rpc.Status, in the grpc-status-details-bin trailer, carrying a semnav.common.v1.ErrorInfo.
import * as grpc from '@grpc/grpc-js';
import { decodeMessage } from './protos';

export interface TypedError {
  code: grpc.status;         // the call's status code
  detailsCode: number;       // RichStatus.code; must equal `code`
  detailsMessage: string;    // RichStatus.message; must equal the call's message
  reason: string;            // ErrorInfo.reason
  field: string;             // ErrorInfo.field
  metadata: Record<string, string>;
}

export function typedError(error: grpc.ServiceError | grpc.StatusObject): TypedError {
  const [bytes] = error.metadata.get('grpc-status-details-bin');
  if (!(bytes instanceof Buffer)) throw new Error(`no grpc-status-details-bin trailer on ${error.code}: ${error.details}`);
  const status = decodeMessage('semnav.common.v1.RichStatus', bytes);
  const detail = status.details.find((any: any) => any.type_url === 'type.googleapis.com/semnav.common.v1.ErrorInfo');
  if (!detail) throw new Error(`no ErrorInfo among ${status.details.map((any: any) => any.type_url).join(', ')}`);
  const info = decodeMessage('semnav.common.v1.ErrorInfo', detail.value);
  return {
    code: error.code,
    detailsCode: status.code,
    detailsMessage: status.message,
    reason: info.reason,
    field: info.field,
    metadata: info.metadata,
  };
}
