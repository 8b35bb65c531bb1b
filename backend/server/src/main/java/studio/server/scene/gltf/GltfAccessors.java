package studio.server.scene.gltf;

import static studio.server.scene.gltf.GltfJson.bad;

import java.util.HashMap;
import java.util.Map;
import java.util.Set;

import tools.jackson.databind.JsonNode;

import studio.engine.memory.MemoryGate;

/**
 * A glTF's accessors read into arrays: every component type the format has (signed and unsigned
 * bytes and shorts, unsigned ints, floats; integers scaled to [0, 1] or [-1, 1] when normalized), at
 * the view's stride. Each accessor is checked to lie within its buffer view before its array is asked
 * of the {@link MemoryGate} and allocated, so an accessor can never cost more than the bytes it reads
 * (at most 8 times as many), and each is read once however many primitives share it. Sparse accessors, and accessors without a buffer view (all zeros), are
 * refused.
 */
final class GltfAccessors {

    private final JsonNode accessors;
    private final GltfBuffers buffers;
    private final MemoryGate memory;
    /** Accessors read already, by index: primitives that share one (a vertex buffer, say) read it once. */
    private final Map<Integer, double[]> read = new HashMap<>();

    GltfAccessors(JsonNode root, GltfBuffers buffers, MemoryGate memory) {
        this.accessors = GltfJson.array(root, "accessors", "");
        this.buffers = buffers;
        this.memory = memory;
    }

    /** Asked before the arrays read from the accessors are allocated. */
    MemoryGate memory() {
        return memory;
    }

    int size() {
        return accessors.size();
    }

    /** The element count of accessor {@code i}. */
    int count(int i) {
        long count = GltfJson.whole(GltfJson.element(accessors, i, "accessors"), "count", 1, Integer.MAX_VALUE, -1,
                "accessors[" + i + "]");
        if (count < 0) {
            throw bad("accessors[" + i + "].count", "is required");
        }
        return (int) count;
    }

    /**
     * Accessor {@code i}'s values, {@code components} per element, as numbers.
     *
     * @param types the component types it may have (glTF's codes: 5126 float, 5121 unsigned byte, ...)
     */
    double[] numbers(int i, String type, int components, Set<Integer> types, String use) {
        Layout l = layout(i, type, components, types, use);
        double[] known = read.get(i);
        if (known != null) {
            return known;
        }
        memory.reserve(MemoryGate.doubles((long) l.count * components));
        double[] out = new double[l.count * components];
        for (int e = 0; e < l.count; e++) {
            long at = l.offset + (long) e * l.stride;
            for (int c = 0; c < components; c++) {
                double v = component(l.view, at + (long) c * l.size, l.componentType, l.normalized);
                if (!Double.isFinite(v)) {
                    throw bad("accessors[" + i + "]", "element " + e + " is not a finite number");
                }
                out[e * components + c] = v;
            }
        }
        read.put(i, out);
        return out;
    }

    /** Accessor {@code i} as vertex indices: unsigned bytes, shorts or ints, each below {@code vertices}. */
    int[] indices(int i, int vertices) {
        Layout l = layout(i, "SCALAR", 1, Set.of(5121, 5123, 5125), "indices");
        if (l.normalized) {
            throw bad("accessors[" + i + "].normalized", "indices are not normalized");
        }
        memory.reserve(MemoryGate.ints(l.count));
        int[] out = new int[l.count];
        for (int e = 0; e < l.count; e++) {
            long at = l.offset + (long) e * l.stride;
            long v = switch (l.componentType) {
                case 5121 -> l.view.u8(at);
                case 5123 -> l.view.u16(at);
                default -> l.view.u32(at);
            };
            if (v >= vertices) {
                throw bad("accessors[" + i + "]", "index " + e + " is " + v + ", but the primitive has " + vertices
                        + " vertices");
            }
            out[e] = (int) v;
        }
        return out;
    }

    private record Layout(Slice view, long offset, int stride, int count, int size, int componentType,
                          boolean normalized) {
    }

    private Layout layout(int i, String type, int components, Set<Integer> types, String use) {
        String path = "accessors[" + i + "]";
        JsonNode a = GltfJson.element(accessors, i, "accessors");
        if (!a.path("sparse").isMissingNode()) {
            throw bad(path + ".sparse", "sparse accessors are not read");
        }
        int componentType = (int) GltfJson.whole(a, "componentType", 0, Integer.MAX_VALUE, -1, path);
        if (!types.contains(componentType)) {
            throw bad(path + ".componentType", componentType + " is not allowed for " + use + " (allowed: "
                    + types + ")");
        }
        String declared = GltfJson.string(a, "type", path);
        if (!type.equals(declared)) {
            throw bad(path + ".type", "must be " + type + " for " + use + ", not " + declared);
        }
        int count = count(i);
        boolean normalized = a.path("normalized").asBoolean(false);
        int size = switch (componentType) {
            case 5120, 5121 -> 1;
            case 5122, 5123 -> 2;
            default -> 4;
        };
        int v = GltfJson.optionalIndex(a, "bufferView", buffers.viewCount(), "bufferViews", path);
        if (v < 0) {
            throw bad(path + ".bufferView", "is required (an accessor of zeros draws nothing)");
        }
        Slice view = buffers.view(v);
        int element = size * components;
        int stride = buffers.stride(v);
        stride = stride == 0 ? element : stride;
        if (stride < element) {
            throw bad("bufferViews[" + v + "].byteStride", stride + " is less than the " + element
                    + "-byte elements of " + path);
        }
        long offset = GltfJson.whole(a, "byteOffset", 0, Integer.MAX_VALUE, 0, path);
        if (offset % size != 0) {
            throw bad(path + ".byteOffset", "must be a multiple of its component size, " + size);
        }
        long end = offset + (long) stride * (count - 1) + element;
        if (end > view.length()) {
            throw bad(path, "its " + count + " elements run past the end of bufferViews[" + v + "] (" + end + " > "
                    + view.length() + " bytes)");
        }
        return new Layout(view, offset, stride, count, size, componentType, normalized);
    }

    private static double component(Slice s, long at, int type, boolean normalized) {
        return switch (type) {
            case 5126 -> s.f32(at);
            case 5120 -> normalized ? Math.max((byte) s.u8(at) / 127.0, -1) : (byte) s.u8(at);
            case 5121 -> normalized ? s.u8(at) / 255.0 : s.u8(at);
            case 5122 -> normalized ? Math.max((short) s.u16(at) / 32767.0, -1) : (short) s.u16(at);
            case 5123 -> normalized ? s.u16(at) / 65535.0 : s.u16(at);
            default -> normalized ? s.u32(at) / 4294967295.0 : s.u32(at);
        };
    }
}
