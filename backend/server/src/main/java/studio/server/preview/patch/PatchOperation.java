package studio.server.preview.patch;

import java.util.ArrayList;
import java.util.List;

import tools.jackson.databind.JsonNode;

/**
 * One operation of a JSON Patch (RFC 6902): what it does, where ({@code path}), from where for
 * {@code move} and {@code copy}, and the value for {@code add}, {@code replace} and {@code test}.
 * Pointers (RFC 6901) are kept as their unescaped tokens: {@code /objects/3/center} is
 * {@code [objects, 3, center]}, {@code ~1} a {@code /} and {@code ~0} a {@code ~} within a token.
 *
 * @param from  the tokens of {@code from}; null unless {@code move} or {@code copy}
 * @param value null unless {@code add}, {@code replace} or {@code test}
 */
public record PatchOperation(Op op, List<String> path, List<String> from, JsonNode value) {

    public enum Op { ADD, REMOVE, REPLACE, MOVE, COPY, TEST }

    /** Tokens a pointer may have: more than any scene needs (a scene is about six levels deep). */
    public static final int MAX_TOKENS = 32;

    /**
     * Reads the operation at {@code field} ({@code patch[i]}).
     *
     * @throws PatchException naming the member at fault
     */
    static PatchOperation of(JsonNode node, String field) {
        if (node == null || !node.isObject()) {
            throw new PatchException(field, "must be an operation: {\"op\": ..., \"path\": ...}");
        }
        JsonNode opNode = node.get("op");
        if (opNode == null || !opNode.isString()) {
            throw new PatchException(field + ".op", "is required: one of add, remove, replace, move, copy, test");
        }
        Op op = switch (opNode.stringValue()) {
            case "add" -> Op.ADD;
            case "remove" -> Op.REMOVE;
            case "replace" -> Op.REPLACE;
            case "move" -> Op.MOVE;
            case "copy" -> Op.COPY;
            case "test" -> Op.TEST;
            default -> throw new PatchException(field + ".op", "unknown operation '" + opNode.stringValue()
                    + "'; must be one of add, remove, replace, move, copy, test");
        };
        boolean hasFrom = op == Op.MOVE || op == Op.COPY;
        boolean hasValue = op == Op.ADD || op == Op.REPLACE || op == Op.TEST;
        for (String member : node.propertyNames()) {
            boolean known = member.equals("op") || member.equals("path") || (hasFrom && member.equals("from"))
                    || (hasValue && member.equals("value"));
            if (!known) {
                throw new PatchException(field + "." + member, "is not a member of a '" + opNode.stringValue()
                        + "' operation");
            }
        }
        List<String> path = pointer(node.get("path"), field + ".path");
        List<String> from = hasFrom ? pointer(node.get("from"), field + ".from") : null;
        JsonNode value = hasValue ? node.get("value") : null;
        if (hasValue && value == null) {
            throw new PatchException(field + ".value", "is required for '" + opNode.stringValue() + "'");
        }
        return new PatchOperation(op, path, from, value);
    }

    /** The tokens of a JSON Pointer (RFC 6901); the whole document is the empty list. */
    static List<String> pointer(JsonNode node, String field) {
        if (node == null || !node.isString()) {
            throw new PatchException(field, "is required: a JSON Pointer such as /objects/0/center");
        }
        String text = node.stringValue();
        List<String> tokens = new ArrayList<>();
        if (text.isEmpty()) {
            return tokens;
        }
        if (text.charAt(0) != '/') {
            throw new PatchException(field, "must be empty or begin with '/'");
        }
        StringBuilder token = new StringBuilder();
        for (int i = 1; i <= text.length(); i++) {
            char c = i < text.length() ? text.charAt(i) : '/';
            if (c == '/') {
                if (tokens.size() == MAX_TOKENS) {
                    throw new PatchException(field, "may have at most " + MAX_TOKENS + " tokens");
                }
                tokens.add(token.toString());
                token.setLength(0);
            } else if (c == '~') {
                char next = i + 1 < text.length() ? text.charAt(i + 1) : 0;
                if (next != '0' && next != '1') {
                    throw new PatchException(field, "'~' must be followed by 0 (for '~') or 1 (for '/')");
                }
                token.append(next == '0' ? '~' : '/');
                i++;
            } else {
                token.append(c);
            }
        }
        return List.copyOf(tokens);
    }

    /** The pointer as written, escapes and all. */
    static String text(List<String> tokens) {
        StringBuilder out = new StringBuilder();
        for (String token : tokens) {
            out.append('/').append(token.replace("~", "~0").replace("/", "~1"));
        }
        return out.toString();
    }
}
