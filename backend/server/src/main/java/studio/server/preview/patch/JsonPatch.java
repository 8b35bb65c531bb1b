package studio.server.preview.patch;

import java.util.ArrayList;
import java.util.Collections;
import java.util.IdentityHashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;

import tools.jackson.databind.JsonNode;
import tools.jackson.databind.node.ArrayNode;
import tools.jackson.databind.node.JsonNodeFactory;
import tools.jackson.databind.node.ObjectNode;

/**
 * A JSON Patch (RFC 6902) applied to a Jackson tree without changing it: each operation copies
 * the containers on its path (copy on write) and links the rest, so a patch of one member of one
 * object of 10,000 copies the root, the objects array's references and that object, and the
 * document it was applied to stays as it was, whether the patch applies or not (a patch applies as
 * a whole or not at all). Written over Jackson 3's tree because the maintained Java libraries of
 * RFC 6902 are written over Jackson 2's.
 *
 * <p>Bounded against a hostile peer: at most {@value #MAX_OPERATIONS} operations, pointers of at
 * most {@value PatchOperation#MAX_TOKENS} tokens, no value placed deeper than {@value #MAX_DEPTH}
 * levels, and {@code copy} operations (and {@code move}s to a deeper place, whose depth must be
 * looked at) that together go through at most a given weight (members, elements and characters), so
 * that a few copies of copies cannot make a document exponentially large, nor a patch of moves
 * take long.
 */
public final class JsonPatch {

    public static final int MAX_OPERATIONS = 1000;
    /** Levels a patched document may have where a patch placed a value. */
    public static final int MAX_DEPTH = 64;

    private final List<PatchOperation> operations;

    private JsonPatch(List<PatchOperation> operations) {
        this.operations = operations;
    }

    /**
     * Reads a patch: a JSON array of operations.
     *
     * @throws PatchException naming {@code patch} or the operation's member at fault
     */
    public static JsonPatch of(JsonNode patch) {
        if (patch == null || !patch.isArray()) {
            throw new PatchException("patch", "must be an array of JSON Patch operations (RFC 6902)");
        }
        if (patch.size() > MAX_OPERATIONS) {
            throw new PatchException("patch", "may have at most " + MAX_OPERATIONS + " operations, not " + patch.size());
        }
        List<PatchOperation> operations = new ArrayList<>(patch.size());
        for (int i = 0; i < patch.size(); i++) {
            operations.add(PatchOperation.of(patch.get(i), "patch[" + i + "]"));
        }
        return new JsonPatch(List.copyOf(operations));
    }

    public List<PatchOperation> operations() {
        return operations;
    }

    /**
     * The document with every operation applied in order; {@code document} itself is not changed.
     *
     * @param maxCopied the weight {@code copy} operations may copy in all (a member, an element or a character weighs 1)
     * @throws PatchException naming the operation that does not apply, and why
     */
    public JsonNode applyTo(JsonNode document, long maxCopied) {
        Application application = new Application(document, maxCopied);
        for (int i = 0; i < operations.size(); i++) {
            application.apply(operations.get(i), "patch[" + i + "]");
        }
        return application.root;
    }

    /** One application: the document so far, the containers it copied (its own to change), and the weight copied. */
    private static final class Application {
        private final Set<JsonNode> own = Collections.newSetFromMap(new IdentityHashMap<>());
        private final long maxCopied;
        private JsonNode root;
        private long copied;

        Application(JsonNode root, long maxCopied) {
            this.root = root;
            this.maxCopied = maxCopied;
        }

        void apply(PatchOperation operation, String field) {
            List<String> path = operation.path();
            switch (operation.op()) {
                case ADD -> add(path, operation.value(), field, true);
                case REMOVE -> remove(path, field);
                case REPLACE -> {
                    at(path, field + ".path");
                    if (!path.isEmpty()) {
                        remove(path, field);
                    }
                    add(path, operation.value(), field, true);
                }
                case MOVE -> {
                    List<String> from = operation.from();
                    if (from.size() < path.size() && path.subList(0, from.size()).equals(from)) {
                        throw new PatchException(field + ".from", "a value cannot be moved into itself");
                    }
                    JsonNode value = at(from, field + ".from");
                    if (!from.equals(path)) {
                        if (path.size() > from.size()) {
                            charge(value, field); // deeper: its depth is looked at, and that work is bounded as copies are
                        }
                        remove(from, field);
                        add(path, value, field, path.size() > from.size());
                    }
                }
                case COPY -> add(path, copy(at(operation.from(), field + ".from"), field), field, true);
                case TEST -> {
                    if (!JsonValues.same(at(path, field + ".path"), operation.value())) {
                        throw new PatchException(field + ".value", "test failed: the value at "
                                + PatchOperation.text(path) + " is not this one");
                    }
                }
            }
        }

        /** The value at a pointer, which must exist. */
        private JsonNode at(List<String> pointer, String field) {
            JsonNode node = root;
            for (String token : pointer) {
                node = child(node, token);
                if (node == null) {
                    throw new PatchException(field, "there is no value at " + PatchOperation.text(pointer));
                }
            }
            return node;
        }

        /** Places a value; {@code deepens}: it may lie deeper than anything in the document yet, so its depth is checked. */
        private void add(List<String> path, JsonNode value, String field, boolean deepens) {
            if (deepens && path.size() + JsonValues.depth(value, MAX_DEPTH + 1) > MAX_DEPTH) {
                throw new PatchException(field + ".path", "the value would lie deeper than " + MAX_DEPTH + " levels");
            }
            if (path.isEmpty()) {
                root = value;
                return;
            }
            JsonNode parent = ownParent(path, field);
            String token = path.get(path.size() - 1);
            if (parent instanceof ObjectNode object) {
                object.set(token, value);
            } else {
                ArrayNode array = (ArrayNode) parent;
                int index = token.equals("-") ? array.size() : index(token, array.size(), field);
                array.insert(index, value);
            }
        }

        private void remove(List<String> path, String field) {
            if (path.isEmpty()) {
                throw new PatchException(field + ".path", "the whole document cannot be removed");
            }
            at(path, field + ".path");
            JsonNode parent = ownParent(path, field);
            String token = path.get(path.size() - 1);
            if (parent instanceof ObjectNode object) {
                object.remove(token);
            } else {
                ((ArrayNode) parent).remove(index(token, parent.size() - 1, field));
            }
        }

        /** The container a path's last token names a place in, made this application's own, with every container above it. */
        private JsonNode ownParent(List<String> path, String field) {
            root = own(root);
            JsonNode node = root;
            for (int i = 0; i < path.size() - 1; i++) {
                JsonNode child = child(node, path.get(i));
                if (child == null || !child.isContainer()) {
                    throw new PatchException(field + ".path", "there is no object or array at "
                            + PatchOperation.text(path.subList(0, i + 1)));
                }
                JsonNode mine = own(child);
                if (mine != child) {
                    replaceChild(node, path.get(i), mine);
                }
                node = mine;
            }
            if (!node.isContainer()) {
                throw new PatchException(field + ".path", "there is no object or array at "
                        + PatchOperation.text(path.subList(0, path.size() - 1)));
            }
            return node;
        }

        /** The container itself if this application copied it, else a shallow copy of it (its members linked). */
        private JsonNode own(JsonNode node) {
            if (own.contains(node) || !node.isContainer()) {
                return node;
            }
            JsonNode copy;
            if (node instanceof ObjectNode object) {
                Map<String, JsonNode> members = new LinkedHashMap<>();
                object.properties().forEach(e -> members.put(e.getKey(), e.getValue()));
                copy = new ObjectNode(JsonNodeFactory.instance, members);
            } else {
                List<JsonNode> elements = new ArrayList<>(node.size());
                node.values().forEach(elements::add);
                copy = new ArrayNode(JsonNodeFactory.instance, elements);
            }
            own.add(copy);
            return copy;
        }

        private JsonNode copy(JsonNode value, String field) {
            charge(value, field);
            return value.deepCopy();
        }

        /** Counts a value's weight against what copies (and moves to deeper places) may go through in all. */
        private void charge(JsonNode value, String field) {
            long weight = JsonValues.weight(value, maxCopied - copied);
            if (weight < 0) {
                throw new PatchException(field + ".from", "copies and moves deeper would go through more than "
                        + maxCopied + " members, elements and characters in all");
            }
            copied += weight;
        }

        private static void replaceChild(JsonNode parent, String token, JsonNode child) {
            if (parent instanceof ObjectNode object) {
                object.set(token, child);
            } else {
                ((ArrayNode) parent).set(Integer.parseInt(token), child);
            }
        }

        /** A container's member or element named by a token; null if there is none. */
        private static JsonNode child(JsonNode node, String token) {
            if (node instanceof ObjectNode object) {
                return object.get(token);
            }
            if (node instanceof ArrayNode array) {
                int index = JsonValues.arrayIndex(token);
                return index >= 0 && index < array.size() ? array.get(index) : null;
            }
            return null;
        }

        private static int index(String token, int max, String field) {
            int index = JsonValues.arrayIndex(token);
            if (index < 0 || index > max) {
                throw new PatchException(field + ".path", "'" + token + "' is not an index from 0 to " + max);
            }
            return index;
        }
    }
}
