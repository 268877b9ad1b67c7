#!/usr/bin/env bash
# A throw-away PKI for the deployment tests: make_test_pki.sh DIR NAME=SANS [NAME=SANS ...]
# writes DIR/ca.{crt,key} and, per NAME, DIR/NAME.{crt,key} signed by that CA for both server
# and client use (mTLS), e.g. `robot=DNS:robot,IP:10.77.1.1`. The same openssl steps as
# docs/operations.md, with short lifetimes.
set -euo pipefail
dir=$1
shift
mkdir -p "$dir"
ec=(-newkey ec -pkeyopt ec_paramgen_curve:prime256v1 -nodes)
openssl req -x509 "${ec[@]}" -days 2 -subj /CN=semnav-test-ca -keyout "$dir/ca.key" -out "$dir/ca.crt" 2>/dev/null
for spec in "$@"; do
  name=${spec%%=*}
  sans=${spec#*=}
  openssl req "${ec[@]}" -subj "/CN=$name" -keyout "$dir/$name.key" -out "$dir/$name.csr" 2>/dev/null
  openssl x509 -req -in "$dir/$name.csr" -CA "$dir/ca.crt" -CAkey "$dir/ca.key" -CAcreateserial -days 2 \
    -extfile <(printf 'subjectAltName=%s\nextendedKeyUsage=serverAuth,clientAuth\n' "$sans") \
    -out "$dir/$name.crt" 2>/dev/null
  rm "$dir/$name.csr"
  chmod 600 "$dir/$name.key"
done
chmod 600 "$dir/ca.key"
