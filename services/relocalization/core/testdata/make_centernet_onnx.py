"""Writes a tiny CenterNet-style ONNX graph for onnx_heads_test.

Input "image" [1, 3, 8, 8] (R, G, B after OpenCV's swapRB). Every head is a 1x1
convolution with fixed weights so that the test can predict each output value:
  heatmap  = [4R - 2, 2R - 1]          (channel sum 6R - 3)
  offset   = [0.25, -0.25]             (bias only)
  size     = [3R + 1, 2R + 1]
  features = [R, G, B, 0.5]
Usage: make_centernet_onnx.py OUT.onnx
"""
import sys

import numpy as np
import onnx
from onnx import TensorProto, helper, numpy_helper


def conv_head(name, weights, bias):
    w = numpy_helper.from_array(np.array(weights, np.float32).reshape(len(weights), 3, 1, 1), name + "_w")
    b = numpy_helper.from_array(np.array(bias, np.float32), name + "_b")
    node = helper.make_node("Conv", ["image", name + "_w", name + "_b"], [name], kernel_shape=[1, 1])
    out = helper.make_tensor_value_info(name, TensorProto.FLOAT, [1, len(weights), 8, 8])
    return node, [w, b], out


def main(path):
    heads = [
        conv_head("heatmap", [[4, 0, 0], [2, 0, 0]], [-2, -1]),
        conv_head("offset", [[0, 0, 0], [0, 0, 0]], [0.25, -0.25]),
        conv_head("size", [[3, 0, 0], [2, 0, 0]], [1, 1]),
        conv_head("features", [[1, 0, 0], [0, 1, 0], [0, 0, 1], [0, 0, 0]], [0, 0, 0, 0.5]),
    ]
    graph = helper.make_graph(
        [h[0] for h in heads], "tiny_centernet",
        [helper.make_tensor_value_info("image", TensorProto.FLOAT, [1, 3, 8, 8])],
        [h[2] for h in heads],
        initializer=[t for h in heads for t in h[1]])
    model = helper.make_model(graph, opset_imports=[helper.make_opsetid("", 11)])
    model.ir_version = 7
    onnx.checker.check_model(model)
    onnx.save(model, path)


if __name__ == "__main__":
    main(sys.argv[1])
