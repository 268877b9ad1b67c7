// One unary gRPC call with mTLS and a bearer token, the .proto files loaded at run time; for the
// three-host test, which needs calls semnavctl does not make (OperatorService.ResolveTarget,
// ModelProxyService.GetUsage).
// Usage: node grpc_call.js PROTO_DIR PROTO_FILE SERVICE METHOD REQUEST_JSON ADDRESS CA CERT KEY TOKEN_FILE
// Prints the response as one JSON line and exits 0, or prints `CODE_NAME: message` on stderr
// and exits 1 (2 for a usage error). NODE_PATH must reach @grpc/grpc-js and @grpc/proto-loader.
"use strict";
const fs = require("fs");
const grpc = require("@grpc/grpc-js");
const protoLoader = require("@grpc/proto-loader");

const args = process.argv.slice(2);
if (args.length !== 10) {
  console.error("usage: grpc_call.js PROTO_DIR PROTO_FILE SERVICE METHOD REQUEST_JSON ADDRESS CA CERT KEY TOKEN_FILE");
  process.exit(2);
}
const [protoDir, protoFile, serviceName, method, requestJson, address, ca, cert, key, tokenFile] = args;

// Field names as in the .proto (and in REQUEST_JSON); unset fields are left out of the output.
const definition = protoLoader.loadSync(protoFile, { includeDirs: [protoDir], keepCase: true, longs: Number, enums: String });
const Service = serviceName.split(".").reduce((node, part) => node[part], grpc.loadPackageDefinition(definition));
const credentials = grpc.credentials.createSsl(fs.readFileSync(ca), fs.readFileSync(key), fs.readFileSync(cert));
const client = new Service(address, credentials);
const metadata = new grpc.Metadata();
metadata.set("authorization", `Bearer ${fs.readFileSync(tokenFile, "utf8").trim()}`);
client[method](JSON.parse(requestJson), metadata, { deadline: Date.now() + 15000 }, (error, response) => {
  if (error) {
    console.error(`${grpc.status[error.code]}: ${error.details}`);
    process.exit(1);
  }
  console.log(JSON.stringify(response));
  client.close();
});
