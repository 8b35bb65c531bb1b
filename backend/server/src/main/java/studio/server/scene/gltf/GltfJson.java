package studio.server.scene.gltf;

import tools.jackson.databind.JsonNode;
import tools.jackson.databind.node.JsonNodeFactory;

/**
 * Values read from a glTF's JSON, each checked as it is read: every problem names where it is by its
 * JSON path in the file ({@code accessors[2].count}).
 */
final class GltfJson {

    private static final JsonNode EMPTY = JsonNodeFactory.instance.arrayNode();

    private GltfJson() {
    }

    static IllegalArgumentException bad(String path, String message) {
        return new IllegalArgumentException(path + ": " + message);
    }

    /** The array {@code name} of {@code node}, empty if absent. */
    static JsonNode array(JsonNode node, String name, String path) {
        JsonNode value = node.path(name);
        if (value.isMissingNode() || value.isNull()) {
            return EMPTY;
        }
        if (!value.isArray()) {
            throw bad(path + name, "must be an array");
        }
        return value;
    }

    /** The object at {@code index} of {@code array}. */
    static JsonNode element(JsonNode array, int index, String path) {
        JsonNode value = array.get(index);
        if (value == null || !value.isObject()) {
            throw bad(path + "[" + index + "]", "must be an object");
        }
        return value;
    }

    /** The whole number {@code field} of {@code node} in [min, max], or {@code fallback} if absent. */
    static long whole(JsonNode node, String field, long min, long max, long fallback, String path) {
        JsonNode value = node.path(field);
        if (value.isMissingNode()) {
            return fallback;
        }
        if (!value.isIntegralNumber() || !value.canConvertToLong() || value.longValue() < min || value.longValue() > max) {
            throw bad(path + "." + field, "must be a whole number from " + min + " to " + max);
        }
        return value.longValue();
    }

    /** A required index into an array of {@code size} elements named {@code what}. */
    static int index(JsonNode node, String field, int size, String what, String path) {
        if (node.path(field).isMissingNode()) {
            throw bad(path + "." + field, "is required");
        }
        return optionalIndex(node, field, size, what, path);
    }

    /** An optional index into an array of {@code size} elements named {@code what}; -1 if absent. */
    static int optionalIndex(JsonNode node, String field, int size, String what, String path) {
        JsonNode value = node.path(field);
        if (value.isMissingNode()) {
            return -1;
        }
        if (!value.isIntegralNumber() || !value.canConvertToInt() || value.intValue() < 0 || value.intValue() >= size) {
            throw bad(path + "." + field, "must name one of the " + size + " " + what + " (0 to " + (size - 1) + ")");
        }
        return value.intValue();
    }

    /** The finite number {@code field} of {@code node}, or {@code fallback} if absent. */
    static double number(JsonNode node, String field, double fallback, String path) {
        JsonNode value = node.path(field);
        if (value.isMissingNode()) {
            return fallback;
        }
        if (!value.isNumber() || !Double.isFinite(value.doubleValue())) {
            throw bad(path + "." + field, "must be a finite number");
        }
        return value.doubleValue();
    }

    /** The array of {@code length} finite numbers {@code field} of {@code node}, or {@code fallback} if absent. */
    static double[] numbers(JsonNode node, String field, int length, double[] fallback, String path) {
        JsonNode value = node.path(field);
        if (value.isMissingNode()) {
            return fallback;
        }
        if (!value.isArray() || value.size() != length) {
            throw bad(path + "." + field, "must be an array of " + length + " numbers");
        }
        double[] out = new double[length];
        for (int i = 0; i < length; i++) {
            JsonNode v = value.get(i);
            if (!v.isNumber() || !Double.isFinite(v.doubleValue())) {
                throw bad(path + "." + field + "[" + i + "]", "must be a finite number");
            }
            out[i] = v.doubleValue();
        }
        return out;
    }

    /** The string {@code field} of {@code node}, or null if absent. */
    static String string(JsonNode node, String field, String path) {
        JsonNode value = node.path(field);
        if (value.isMissingNode()) {
            return null;
        }
        if (!value.isString()) {
            throw bad(path + "." + field, "must be a string");
        }
        return value.asString();
    }
}
