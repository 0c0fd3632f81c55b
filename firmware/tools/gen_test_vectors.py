#!/usr/bin/env python3
"""Turn protocol/test-vectors.json into a C include for the tests.
usage: gen_test_vectors.py test-vectors.json out.h"""
import json, sys

def arr(h):
    b = bytes.fromhex(h.replace(" ", "")) if h else b""
    return "{" + ",".join("0x%02X" % x for x in b) + ("" if b else "0") + "}", len(b)

def main():
    d = json.load(open(sys.argv[1]))
    out = ["/* GENERATED from protocol/test-vectors.json by tools/gen_test_vectors.py. Do not edit. */",
           "#include <stdint.h>", "typedef struct { const char *name; const uint8_t *frame; uint16_t frame_len;",
           "  int kind; /* 0 instruction, 1 status, 2 invalid */ int valid; int id; int instruction;",
           "  const uint8_t *params; uint16_t params_len; int error; } tv_vector;"]
    for i, v in enumerate(d["vectors"]):
        a, _ = arr(v["hex"])
        out.append("static const uint8_t tv_f%d[] = %s;" % (i, a))
        p, _ = arr(v["params_hex"] or "")
        out.append("static const uint8_t tv_p%d[] = %s;" % (i, p))
    out.append("static const tv_vector tv_vectors[] = {")
    for i, v in enumerate(d["vectors"]):
        _, fl = arr(v["hex"])
        _, pl = arr(v["params_hex"] or "")
        kind = {"instruction": 0, "status": 1, "invalid": 2}[v["kind"]]
        out.append('  {"%s", tv_f%d, %d, %d, %d, %d, %d, tv_p%d, %d, %d},' % (
            v["name"], i, fl, kind, 1 if v["valid"] else 0, v["id"] if v["id"] is not None else -1,
            v["instruction"] if v["instruction"] is not None else -1, i, pl,
            v["error"] if v["error"] is not None else -1))
    out.append("};")
    out.append("#define TV_COUNT %d" % len(d["vectors"]))
    # exchanges: steps of (request, expected reply or none) against a fresh module
    out.append("typedef struct { const uint8_t *request; uint16_t request_len; const uint8_t *reply; uint16_t reply_len; } tv_step;")
    out.append("typedef struct { const char *name; const tv_step *steps; int step_count; } tv_exchange;")
    for i, x in enumerate(d.get("exchanges", [])):
        for j, st in enumerate(x["steps"]):
            out.append("static const uint8_t tx_q%d_%d[] = %s;" % (i, j, arr(st["request_hex"])[0]))
            out.append("static const uint8_t tx_r%d_%d[] = %s;" % (i, j, arr(st["reply_hex"])[0]))
        out.append("static const tv_step tx_s%d[] = {%s};" % (i, ",".join(
            "{tx_q%d_%d, %d, tx_r%d_%d, %d}" % (i, j, arr(st["request_hex"])[1], i, j, arr(st["reply_hex"])[1])
            for j, st in enumerate(x["steps"]))))
    out.append("static const tv_exchange tv_exchanges[] = {")
    for i, x in enumerate(d.get("exchanges", [])):
        out.append('  {"%s", tx_s%d, %d},' % (x["name"], i, len(x["steps"])))
    out.append("};")
    out.append("#define TV_EXCHANGE_COUNT %d" % len(d.get("exchanges", [])))
    open(sys.argv[2], "w").write("\n".join(out) + "\n")

if __name__ == "__main__":
    main()
