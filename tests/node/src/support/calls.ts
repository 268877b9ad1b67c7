// Promise-shaped gRPC calls over the dynamically loaded clients.
import * as grpc from '@grpc/grpc-js';

export function deadline(ms = 10000): grpc.Deadline {
  return new Date(Date.now() + ms);
}

// A unary call; rejects with the grpc.ServiceError (code, details, trailing metadata).
export function unary<T = any>(client: grpc.Client, method: string, request: object): Promise<T> {
  return new Promise((resolve, reject) => {
    (client as any)[method](request, { deadline: deadline() }, (error: grpc.ServiceError | null, response: T) =>
      error ? reject(error) : resolve(response));
  });
}

// The error a call must fail with; fails the test when the call succeeds.
export async function callError(call: Promise<unknown>): Promise<grpc.ServiceError> {
  try {
    await call;
  } catch (error) {
    return error as grpc.ServiceError;
  }
  throw new Error('the call succeeded but an error was expected');
}

type Stream<T> = grpc.ClientReadableStream<T> | grpc.ClientDuplexStream<unknown, T>;

// Reads a server (or bidi) stream message by message with a timeout per message.
export class StreamReader<T = any> {
  private readonly queued: T[] = [];
  private waiter: (() => void) | null = null;
  private error: grpc.ServiceError | null = null;
  private readonly status: Promise<grpc.StatusObject>;

  constructor(readonly stream: Stream<T>) {
    stream.on('data', (message: T) => this.push(() => this.queued.push(message)));
    stream.on('error', (error: grpc.ServiceError) => this.push(() => (this.error = error)));
    this.status = new Promise((resolve) => stream.on('status', resolve));
  }

  // The next message; rejects when the stream ended or failed first, or after timeoutMs.
  async next(timeoutMs = 10000): Promise<T> {
    const limit = Date.now() + timeoutMs;
    while (this.queued.length === 0) {
      if (this.error) throw this.error;
      if (this.ended()) throw new Error('stream ended without another message');
      const left = limit - Date.now();
      if (left <= 0) throw new Error(`no message within ${timeoutMs} ms`);
      await new Promise<void>((resolve) => {
        const timer = setTimeout(resolve, left);
        this.waiter = () => {
          clearTimeout(timer);
          resolve();
        };
      });
    }
    return this.queued.shift()!;
  }

  // Every message until the stream ends, then its final status.
  async drain(): Promise<{ messages: T[]; status: grpc.StatusObject }> {
    const status = await this.status;
    return { messages: this.queued.splice(0), status };
  }

  cancel(): void {
    this.stream.cancel();
  }

  private ended(): boolean {
    return (this.stream as any).readableEnded || (this.stream as any).destroyed;
  }

  private push(update: () => void): void {
    update();
    this.waiter?.();
    this.waiter = null;
  }
}
