// Proxy configuration from flags, then SEMNAV_WEB_* environment variables, then defaults.
import * as path from "node:path";

// The checkout's protos/ folder, fixed by the build (build.mjs).
declare const DEFAULT_PROTO_DIR: string;

export interface TlsConfig {
  caFile?: string;       // PEM CA bundle that signed the upstream servers; set = TLS on
  certFile?: string;     // client certificate for mTLS
  keyFile?: string;      // its key
  serverName?: string;   // name to verify when dialling an IP address
}

export interface ProxyConfig {
  listen: string;          // host:port of the HTTP server
  gateway: string;         // OperatorService
  mapping: string;         // MappingService (grid, scene graph)
  planning: string;        // PlanningService (paths, frontiers)
  protoDir: string;        // root of the .proto tree, loaded at start-up
  staticDir: string;       // the built page
  robotId: string;         // robot the page shows first
  upstreamToken?: string;  // bearer token used when a browser request brings none
  deadlineMs: number;      // deadline of unary calls without grpc-timeout / timeout_ms
  verbose: boolean;        // log every API request (level=info), not only problems
  tls: TlsConfig;
}

interface FlagSpec {
  name: string;
  env: string;
  value: string;
  help: string;
  apply: (config: ProxyConfig, value: string) => void;
}

const FLAGS: FlagSpec[] = [
  { name: "listen", env: "SEMNAV_WEB_LISTEN", value: "HOST:PORT", help: "HTTP listen address (default 127.0.0.1:8080)", apply: (c, v) => (c.listen = v) },
  { name: "gateway", env: "SEMNAV_WEB_GATEWAY", value: "ADDR", help: "gateway OperatorService (default 127.0.0.1:50050)", apply: (c, v) => (c.gateway = v) },
  { name: "mapping", env: "SEMNAV_WEB_MAPPING", value: "ADDR", help: "MappingService (default 127.0.0.1:50051)", apply: (c, v) => (c.mapping = v) },
  { name: "planning", env: "SEMNAV_WEB_PLANNING", value: "ADDR", help: "PlanningService (default 127.0.0.1:50052)", apply: (c, v) => (c.planning = v) },
  { name: "protos", env: "SEMNAV_WEB_PROTOS", value: "DIR", help: `proto root (default ${DEFAULT_PROTO_DIR})`, apply: (c, v) => (c.protoDir = v) },
  { name: "static", env: "SEMNAV_WEB_STATIC", value: "DIR", help: "built page folder (default ./static beside the server bundle)", apply: (c, v) => (c.staticDir = v) },
  { name: "robot-id", env: "SEMNAV_WEB_ROBOT_ID", value: "ID", help: "robot shown first (default sim-robot)", apply: (c, v) => (c.robotId = v) },
  { name: "token-env", env: "SEMNAV_WEB_TOKEN_ENV", value: "VAR", help: "environment variable holding the upstream bearer token used when the browser sends none", apply: (c, v) => (c.upstreamToken = process.env[v]) },
  { name: "deadline-ms", env: "SEMNAV_WEB_DEADLINE_MS", value: "MS", help: "deadline of unary calls without grpc-timeout (default 10000)", apply: (c, v) => (c.deadlineMs = positiveInt("deadline-ms", v)) },
  { name: "log-level", env: "SEMNAV_WEB_LOG_LEVEL", value: "LEVEL", help: "warning (default) or info: info logs start-up and every API request", apply: (c, v) => (c.verbose = logLevel(v)) },
  { name: "tls-ca", env: "SEMNAV_WEB_TLS_CA", value: "FILE", help: "PEM CA of the upstream servers: TLS on", apply: (c, v) => (c.tls.caFile = v) },
  { name: "tls-cert", env: "SEMNAV_WEB_TLS_CERT", value: "FILE", help: "client certificate for upstream mTLS", apply: (c, v) => (c.tls.certFile = v) },
  { name: "tls-key", env: "SEMNAV_WEB_TLS_KEY", value: "FILE", help: "client key for upstream mTLS", apply: (c, v) => (c.tls.keyFile = v) },
  { name: "tls-server-name", env: "SEMNAV_WEB_TLS_SERVER_NAME", value: "NAME", help: "server name to verify when dialling an IP", apply: (c, v) => (c.tls.serverName = v) },
];

function logLevel(value: string): boolean {
  if (value !== "info" && value !== "warning") throw new Error(`--log-level: expected info or warning, got '${value}'`);
  return value === "info";
}

function positiveInt(flag: string, value: string): number {
  const n = Number(value);
  if (!Number.isInteger(n) || n <= 0) throw new Error(`--${flag}: expected a positive integer, got '${value}'`);
  return n;
}

export function usage(): string {
  const lines = FLAGS.map((f) => `  --${`${f.name} ${f.value}`.padEnd(24)} ${f.help} [$${f.env}]`);
  return `usage: node semnav-dashboard.js [flags]\n${lines.join("\n")}\n  --help                   this text\n`;
}

// Throws an Error naming the flag on bad input; returns undefined when --help was asked.
export function parseConfig(argv: string[], env: NodeJS.ProcessEnv, bundleDir: string): ProxyConfig | undefined {
  const config: ProxyConfig = {
    listen: "127.0.0.1:8080",
    gateway: "127.0.0.1:50050",
    mapping: "127.0.0.1:50051",
    planning: "127.0.0.1:50052",
    protoDir: DEFAULT_PROTO_DIR,
    staticDir: path.join(bundleDir, "static"),
    robotId: "sim-robot",
    deadlineMs: 10000,
    verbose: false,
    tls: {},
  };
  for (const flag of FLAGS) {
    const value = env[flag.env];
    if (value !== undefined && value !== "") flag.apply(config, value);
  }
  for (let i = 0; i < argv.length; ++i) {
    const arg = argv[i];
    if (arg === "--help" || arg === "-h") return undefined;
    const [name, inline] = arg.startsWith("--") ? arg.slice(2).split(/=(.*)/s, 2) : [arg, undefined];
    const flag = FLAGS.find((f) => f.name === name);
    if (flag === undefined) throw new Error(`unknown flag '${arg}'`);
    const value = inline ?? argv[++i];
    if (value === undefined) throw new Error(`--${flag.name}: missing ${flag.value}`);
    flag.apply(config, value);
  }
  if ((config.tls.certFile === undefined) !== (config.tls.keyFile === undefined)) {
    throw new Error("--tls-cert and --tls-key: give both or neither");
  }
  return config;
}
