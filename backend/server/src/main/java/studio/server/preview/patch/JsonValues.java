package studio.server.preview.patch;

import java.util.Iterator;
import java.util.Map;

import tools.jackson.databind.JsonNode;

/** What a JSON Patch asks of JSON values: equality as RFC 6902's {@code test} means it, depth, weight, indices. */
final class JsonValues {

    private JsonValues() {
    }

    /** Equal as RFC 6902 says: numbers by their value (1 and 1.0), objects whatever their members' order. */
    static boolean same(JsonNode a, JsonNode b) {
        if (a.isNumber() && b.isNumber()) {
            return a.decimalValue().compareTo(b.decimalValue()) == 0;
        }
        if (a.isObject() && b.isObject()) {
            if (a.size() != b.size()) {
                return false;
            }
            for (Map.Entry<String, JsonNode> member : a.properties()) {
                JsonNode other = b.get(member.getKey());
                if (other == null || !same(member.getValue(), other)) {
                    return false;
                }
            }
            return true;
        }
        if (a.isArray() && b.isArray()) {
            if (a.size() != b.size()) {
                return false;
            }
            for (int i = 0; i < a.size(); i++) {
                if (!same(a.get(i), b.get(i))) {
                    return false;
                }
            }
            return true;
        }
        return a.equals(b);
    }

    /** Levels of a value (a scalar is 0, {@code [1]} is 1), counted no further than {@code cap}. */
    static int depth(JsonNode value, int cap) {
        if (value == null || !value.isContainer() || cap <= 0) {
            return 0;
        }
        int deepest = 0;
        for (Iterator<JsonNode> it = value.values().iterator(); it.hasNext() && deepest < cap - 1; ) {
            deepest = Math.max(deepest, depth(it.next(), cap - 1));
        }
        return 1 + deepest;
    }

    /** Members, elements and characters of a value, or -1 once past {@code max}. */
    static long weight(JsonNode value, long max) {
        long weight = value.isString() ? value.stringValue().length() : 1;
        if (value.isContainer()) {
            for (Map.Entry<String, JsonNode> member : value.properties()) {
                weight += member.getKey().length();
            }
            for (JsonNode child : value.values()) {
                if (weight > max) {
                    return -1;
                }
                long w = weight(child, max - weight);
                if (w < 0) {
                    return -1;
                }
                weight += w;
            }
        }
        return weight > max ? -1 : weight;
    }

    /** An array index token (RFC 6901: 0 or digits without a leading zero), or -1. */
    static int arrayIndex(String token) {
        int length = token.length();
        if (length == 0 || length > 9 || (length > 1 && token.charAt(0) == '0')) {
            return -1;
        }
        for (int i = 0; i < length; i++) {
            if (token.charAt(i) < '0' || token.charAt(i) > '9') {
                return -1;
            }
        }
        return Integer.parseInt(token);
    }
}
