package studio.server.preview;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;

import studio.server.preview.patch.JsonPatch;
import studio.server.preview.patch.PatchException;
import studio.server.scene.format.FieldProblem;
import studio.server.scene.format.InvalidSceneException;
import tools.jackson.core.JacksonException;
import tools.jackson.core.JsonParser;
import tools.jackson.core.JsonToken;
import tools.jackson.core.ObjectReadContext;
import tools.jackson.core.json.JsonFactory;

/**
 * One message of the live view: a whole scene, {@code {"revision": n, "scene": {...}, "width": w,
 * "height": h}}, or a patch to the scene of revision m, {@code {"revision": n, "base": m, "patch":
 * [RFC 6902 operations], "width": w, "height": h}}. A scene is kept as the bytes the client sent,
 * for the same reading as {@code POST /api/render} (a streaming pass finds where it starts and ends,
 * so a large inline mesh is not copied through a tree); a patch is read as a Jackson tree
 * ({@link JsonPatch}, bounded).
 *
 * <p>Streaming, not a Jackson tree: 3.5 ms a 10,000-sphere drag step against 14-15 (PreviewReadingBench).
 *
 * @param revision the client's revision number, increasing within a session
 * @param scene    the scene's JSON
 * @param objects  where the elements of the scene's objects array lie in {@code scene}, found in the same
 *                 pass ({@link SceneObjectsInJson}), or null
 * @param base     the revision a patch applies to; -1 for a whole scene
 * @param patch    the patch, or null for a whole scene (then {@code scene} is not null)
 * @param width    the view's width in pixels, or 0 for the scene's own
 * @param height   the view's height in pixels, or 0 for the scene's own
 */
record PreviewRequest(long revision, byte[] scene, int[] objects, long base, JsonPatch patch, int width, int height) {

    private static final JsonFactory JSON = new JsonFactory();

    /**
     * Reads a message.
     *
     * @throws InvalidSceneException naming {@code revision}, {@code scene}, {@code base}, {@code patch} (or
     *                               its operation's member), {@code width} or {@code height}
     */
    static PreviewRequest parse(byte[] message, int maxWidth, int maxHeight) {
        Long revision = null;
        byte[] scene = null;
        int[] objects = null;
        Long base = null;
        JsonPatch patch = null;
        boolean patchGiven = false;
        Integer width = null, height = null;
        List<FieldProblem> problems = new ArrayList<>();
        try (JsonParser parser = JSON.createParser(ObjectReadContext.empty(), message)) {
            if (parser.nextToken() != JsonToken.START_OBJECT) {
                throw new InvalidSceneException("", "expected a JSON object {\"revision\": n, \"scene\": {...}}");
            }
            while (parser.nextToken() == JsonToken.PROPERTY_NAME) {
                String name = parser.currentName();
                JsonToken value = parser.nextToken();
                switch (name) {
                    case "revision" -> revision = wholeNumber(parser, value, "revision", 0, Long.MAX_VALUE, problems);
                    case "base" -> base = wholeNumber(parser, value, "base", 0, Long.MAX_VALUE, problems);
                    case "patch" -> {
                        patchGiven = true;
                        int start = (int) parser.currentTokenLocation().getByteOffset();
                        parser.skipChildren();
                        int end = (int) parser.currentLocation().getByteOffset();
                        patch = patch(Arrays.copyOfRange(message, start, end), problems);
                    }
                    case "width" -> width = size(parser, value, "width", maxWidth, problems);
                    case "height" -> height = size(parser, value, "height", maxHeight, problems);
                    case "scene" -> {
                        if (value != JsonToken.START_OBJECT) {
                            problems.add(new FieldProblem("scene", "must be a scene (a JSON object)"));
                            parser.skipChildren();
                        } else {
                            int start = (int) parser.currentTokenLocation().getByteOffset();
                            objects = SceneObjectsInJson.scan(parser, message, start); // reads the scene to its end
                            int end = (int) parser.currentLocation().getByteOffset();
                            scene = Arrays.copyOfRange(message, start, end);
                        }
                    }
                    default -> {
                        problems.add(new FieldProblem(name, "unknown field; a live-view message has revision, "
                                + "scene or base and patch, width and height"));
                        parser.skipChildren();
                    }
                }
            }
            if (parser.nextToken() != null) {
                problems.add(new FieldProblem("", "unexpected content after the message's closing '}'"));
            }
        } catch (JacksonException e) {
            var at = e.getLocation();
            throw new InvalidSceneException("", "malformed JSON" + (at != null ? " at line " + at.getLineNr()
                    + ", column " + at.getColumnNr() : "") + "; expected {\"revision\": n, \"scene\": {...}}");
        }
        if (revision == null && problems.stream().noneMatch(p -> p.field().equals("revision"))) {
            problems.add(new FieldProblem("revision", "is required: a whole number that grows with every message"));
        }
        boolean sceneGiven = scene != null || problems.stream().anyMatch(p -> p.field().equals("scene"));
        if (sceneGiven && patchGiven) {
            problems.add(new FieldProblem("patch", "a message has a scene or a patch, not both"));
        } else if (!sceneGiven && !patchGiven) {
            problems.add(new FieldProblem("scene", "is required (or base and patch, after a first scene)"));
        }
        if (patchGiven && base == null && problems.stream().noneMatch(p -> p.field().equals("base"))) {
            problems.add(new FieldProblem("base", "is required with a patch: the revision it applies to"));
        }
        if (!patchGiven && base != null) {
            problems.add(new FieldProblem("base", "is only for a patch"));
        }
        if (!problems.isEmpty()) {
            throw new InvalidSceneException(problems);
        }
        return new PreviewRequest(revision, scene, objects, base != null ? base : -1, patch,
                width != null ? width : 0, height != null ? height : 0);
    }

    /** A patch's operations, read from its JSON (duplicate members refused); null with a problem if they do not read. */
    private static JsonPatch patch(byte[] json, List<FieldProblem> problems) {
        try {
            return JsonPatch.of(PatchBase.TREES.readTree(json));
        } catch (PatchException e) {
            problems.add(new FieldProblem(e.field(), e.getMessage()));
        } catch (JacksonException e) {
            problems.add(new FieldProblem("patch", "is not well-formed: " + e.getOriginalMessage()));
        }
        return null;
    }

    /**
     * Whether a message holds a whole scene (a {@code scene} member before any {@code patch}), read
     * only as far as that member's name: a whole scene makes every message before it moot.
     */
    static boolean isWholeScene(byte[] message) {
        try (JsonParser parser = JSON.createParser(ObjectReadContext.empty(), message)) {
            if (parser.nextToken() != JsonToken.START_OBJECT) {
                return false;
            }
            while (parser.nextToken() == JsonToken.PROPERTY_NAME) {
                String name = parser.currentName();
                if (name.equals("scene") || name.equals("patch")) {
                    return name.equals("scene");
                }
                parser.nextToken();
                parser.skipChildren();
            }
        } catch (JacksonException e) {
            // as far as it could be read
        }
        return false;
    }

    /** The revision number of a message that cannot be read as a whole, if it can be found; else null. */
    static Long revisionOf(byte[] message) {
        try (JsonParser parser = JSON.createParser(ObjectReadContext.empty(), message)) {
            if (parser.nextToken() != JsonToken.START_OBJECT) {
                return null;
            }
            while (parser.nextToken() == JsonToken.PROPERTY_NAME) {
                String name = parser.currentName();
                JsonToken value = parser.nextToken();
                if (name.equals("revision") && value == JsonToken.VALUE_NUMBER_INT && fitsLong(parser)) {
                    return parser.getLongValue();
                }
                parser.skipChildren();
            }
        } catch (JacksonException e) {
            // as far as it could be read
        }
        return null;
    }

    private static boolean fitsLong(JsonParser parser) {
        JsonParser.NumberType type = parser.getNumberType();
        return type == JsonParser.NumberType.INT || type == JsonParser.NumberType.LONG;
    }

    private static Integer size(JsonParser parser, JsonToken value, String field, int max, List<FieldProblem> problems) {
        Long size = wholeNumber(parser, value, field, 1, max, problems);
        return size != null ? size.intValue() : null;
    }

    private static Long wholeNumber(JsonParser parser, JsonToken value, String field, long min, long max,
                                    List<FieldProblem> problems) {
        if (value != JsonToken.VALUE_NUMBER_INT || !fitsLong(parser)
                || parser.getLongValue() < min || parser.getLongValue() > max) {
            problems.add(new FieldProblem(field, "must be a whole number from " + min + " to " + max));
            parser.skipChildren();
            return null;
        }
        return parser.getLongValue();
    }
}
