#!/bin/sh
# Rewrites the committed v1 baseline image from protos/ as they are now. Run it only after a
# deliberate, reviewed change of the contract (see docs/protocol.md, "Compatibility policy"):
#   protos/baseline/update.sh && git add protos/baseline/semnav-v1.binpb
set -eu
protos=$(cd "$(dirname "$0")/.." && pwd)
cd "$protos"
"$protos/../node_modules/.bin/buf" build -o baseline/semnav-v1.binpb
echo "updated $protos/baseline/semnav-v1.binpb"
