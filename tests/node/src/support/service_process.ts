// A real semnav binary on a loopback port, as tests/support/service_process.h does for the C++
// contract tests: `--listen 127.0.0.1:0`, then the address from its "<binary> serving on
// <host>:<port>" line (printed once the server is healthy). SEMNAV_BIN_DIR holds the binaries.
import { ChildProcess, spawn } from 'node:child_process';
import * as fs from 'node:fs';
import * as os from 'node:os';
import * as path from 'node:path';

const binDir = process.env.SEMNAV_BIN_DIR ?? '';

export interface ServiceProcess {
  address: string;
  // SIGTERM, then the exit code (the services exit 0 on SIGTERM).
  stop(): Promise<number | null>;
}

export async function startService(binary: string, args: string[] = [], timeoutMs = 20000): Promise<ServiceProcess> {
  const file = path.join(binDir, binary);
  if (!binDir || !fs.existsSync(file)) throw new Error(`${file} not built (SEMNAV_BIN_DIR=${binDir})`);
  const child = spawn(file, [...args, '--listen', '127.0.0.1:0'], { stdio: ['ignore', 'pipe', 'inherit'] });
  const exited = new Promise<number | null>((resolve) => child.once('exit', (code) => resolve(code)));
  // Never outlive the test process, even when it dies before its after() hooks.
  const killOnExit = () => child.kill('SIGKILL');
  process.once('exit', killOnExit);
  exited.then(() => process.removeListener('exit', killOnExit));
  const address = await servingAddress(child, binary, timeoutMs);
  return {
    address,
    stop: async () => {
      child.kill('SIGTERM');
      return exited;
    },
  };
}

function servingAddress(child: ChildProcess, binary: string, timeoutMs: number): Promise<string> {
  return new Promise((resolve, reject) => {
    let printed = '';
    const done = () => {
      clearTimeout(timer);
      child.removeListener('exit', onExit);
      child.stdout!.removeListener('data', onData);
      child.stdout!.resume();  // keep draining so the child never blocks on a full pipe
    };
    const fail = (why: string) => {
      done();
      child.kill('SIGKILL');
      reject(new Error(`${binary} ${why}: ${printed}`));
    };
    const onExit = (code: number | null) => fail(`exited with ${code}`);
    const onData = (data: Buffer) => {
      printed += data.toString();
      const match = /serving on (\S+)\n/.exec(printed);
      if (!match) return;
      done();
      resolve(match[1]);
    };
    const timer = setTimeout(() => fail(`did not print "serving on" within ${timeoutMs} ms`), timeoutMs);
    child.once('exit', onExit);
    child.stdout!.on('data', onData);
  });
}

// A fresh temporary folder for one test (config files, map stores).
export function tempDir(prefix: string): string {
  return fs.mkdtempSync(path.join(process.env.TMPDIR ?? os.tmpdir(), `semnav-node-${prefix}-`));
}
