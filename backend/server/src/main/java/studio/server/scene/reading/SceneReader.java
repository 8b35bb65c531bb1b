package studio.server.scene.reading;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.Comparator;
import java.util.List;
import java.util.Map;
import java.util.function.Supplier;
import java.util.stream.Collectors;

import com.fasterxml.jackson.annotation.JsonSubTypes;

import jakarta.validation.ElementKind;
import jakarta.validation.Path;
import jakarta.validation.Validator;
import tools.jackson.core.JacksonException;
import tools.jackson.core.JsonParser;
import tools.jackson.core.StreamReadFeature;
import tools.jackson.core.TokenStreamLocation;
import tools.jackson.core.exc.InputCoercionException;
import tools.jackson.databind.DeserializationFeature;
import tools.jackson.databind.JsonNode;
import tools.jackson.databind.MapperFeature;
import tools.jackson.databind.cfg.CoercionAction;
import tools.jackson.databind.cfg.CoercionInputShape;
import tools.jackson.databind.type.LogicalType;
import tools.jackson.databind.exc.InvalidTypeIdException;
import tools.jackson.databind.exc.MismatchedInputException;
import tools.jackson.databind.exc.UnrecognizedPropertyException;
import tools.jackson.databind.json.JsonMapper;
import tools.jackson.databind.node.JsonNodeFactory;
import tools.jackson.databind.node.ObjectNode;

import studio.server.scene.format.FieldProblem;
import studio.server.scene.format.InvalidSceneException;
import studio.server.scene.format.SceneDto;

/**
 * Reads scene JSON strictly (unknown fields, duplicate keys, numbers as strings, fractions for
 * whole numbers, {@code null} for a field and trailing garbage are all errors) and validates it with
 * Bean Validation. Every problem is reported with the JSON path of its field.
 */
public final class SceneReader {

    /** Plainly valid scenes skip Jackson's binding and the validator (see {@link FastPathBinder}). */
    private static final FastPathBinder FAST_PATH = new FastPathBinder(SceneDto.class);

    /**
     * The full path's data-binding mapper, built on first use: a valid scene's bytes are read by
     * {@link PlainTreeReader} and bound by the fast path without it (building it took 25-42 ms of a
     * cold command line).
     */
    static final class FullPath {
        static final JsonMapper MAPPER = JsonMapper.builder()
                .enable(DeserializationFeature.FAIL_ON_UNKNOWN_PROPERTIES)
                .enable(DeserializationFeature.FAIL_ON_TRAILING_TOKENS)
                .enable(DeserializationFeature.FAIL_ON_NULL_FOR_PRIMITIVES)
                .enable(DeserializationFeature.FAIL_ON_INVALID_SUBTYPE)
                .disable(DeserializationFeature.ACCEPT_FLOAT_AS_INT)
                .disable(MapperFeature.ALLOW_COERCION_OF_SCALARS)
                .enable(StreamReadFeature.STRICT_DUPLICATE_DETECTION)
                // a number or boolean where text belongs ("name": 123) is an error, not silently text
                .withCoercionConfig(LogicalType.Textual, text -> text
                        .setCoercion(CoercionInputShape.Integer, CoercionAction.Fail)
                        .setCoercion(CoercionInputShape.Float, CoercionAction.Fail)
                        .setCoercion(CoercionInputShape.Boolean, CoercionAction.Fail))
                .build();
    }

    private final boolean fastPath;
    private final boolean fastDoubles;
    private final Supplier<Validator> validator;

    public SceneReader(Validator validator) {
        this(() -> validator);
    }

    /** @param validator asked for only when a scene takes the full path (the CLI then never boots it for a valid scene) */
    public SceneReader(Supplier<Validator> validator) {
        this(validator, true, true);
    }

    /**
     * A reader for a process that reads one scene (the command line): the same scenes, with the
     * JDK's parser of fractions, which costs nothing to start (see {@link PlainTreeReader}).
     */
    public static SceneReader forOneScene(Supplier<Validator> validator) {
        return new SceneReader(validator, true, false);
    }

    /**
     * @param fastPath    whether plainly valid scenes take the fast path (tests compare both ways)
     * @param fastDoubles whether fractions are parsed by Jackson's parser rather than the JDK's
     */
    SceneReader(Supplier<Validator> validator, boolean fastPath, boolean fastDoubles) {
        this.validator = validator;
        this.fastPath = fastPath;
        this.fastDoubles = fastDoubles;
    }

    /**
     * Parses and validates a scene.
     *
     * @param overrides values set before validation by JSON path of an object field, such as
     *                  {@code "image.width" -> 320} (the CLI's --width)
     * @throws InvalidSceneException listing every problem found
     */
    public SceneDto read(byte[] json, Map<String, Object> overrides) {
        SceneDto scene;
        List<FieldProblem> nulls = new ArrayList<>();
        JsonNode tree = readTree(json);
        if (tree == null || tree.isMissingNode()) {
            throw new InvalidSceneException("", "the request body is empty; expected a scene as a JSON object");
        }
        if (!tree.isObject()) {
            throw new InvalidSceneException("", "expected a scene as a JSON object, not " + tree.getNodeType()
                    .toString().toLowerCase());
        }
        try {
            dropNullFields(tree, new StringBuilder(), nulls);
            applyOverrides((ObjectNode) tree, overrides);
            if (fastPath && nulls.isEmpty()) {
                SceneDto fast = FAST_PATH.bind(tree);
                if (fast != null) {
                    return fast;
                }
            }
            scene = FullPath.MAPPER.treeToValue(tree, SceneDto.class);
        } catch (JacksonException e) {
            throw new InvalidSceneException(withNulls(nulls, List.of(problemOf(e))));
        }
        List<FieldProblem> problems = new ArrayList<>();
        validator.get().validate(scene).forEach(v -> problems.add(new FieldProblem(pathOf(v.getPropertyPath()), v.getMessage())));
        return checked(scene, withNulls(nulls, problems));
    }

    /**
     * The scene's JSON as a tree (null for an empty body): a well-formed object by the streaming
     * parser alone, anything else by the mapper. The mapper's parser is kept, so that where it
     * failed can be told by JSON path ({@link MalformedJson}).
     */
    private JsonNode readTree(byte[] json) {
        JsonNode plain = PlainTreeReader.read(json, fastDoubles);
        if (plain != null) {
            return plain;
        }
        try (JsonParser parser = FullPath.MAPPER.createParser(json)) {
            try {
                return FullPath.MAPPER.readTree(parser);
            } catch (MismatchedInputException trailing) {
                // reading a tree can only mismatch on content after the scene (FAIL_ON_TRAILING_TOKENS)
                TokenStreamLocation at = trailing.getLocation();
                throw new InvalidSceneException("", "malformed JSON at line " + at.getLineNr() + ", column "
                        + at.getColumnNr() + ": " + MalformedJson.AFTER_THE_SCENE);
            } catch (JacksonException e) {
                throw new InvalidSceneException(List.of(MalformedJson.problem(e, parser, json)));
            }
        }
    }

    private static SceneDto checked(SceneDto scene, List<FieldProblem> problems) {
        if (!problems.isEmpty()) {
            problems.sort(Comparator.comparing(FieldProblem::field).thenComparing(FieldProblem::message));
            throw new InvalidSceneException(problems);
        }
        return scene;
    }

    public SceneDto read(byte[] json) {
        return read(json, Map.of());
    }

    /**
     * Removes every object member whose value is {@code null}, noting a problem for each: a field is
     * given or left out (for its default), as the published schema says. Null elements of lists stay,
     * for Bean Validation to name ("must be a number"). The path is built in one buffer, and made a
     * string only for a null found (a scene of 10,000 objects has some 100,000 members).
     */
    private static void dropNullFields(JsonNode node, StringBuilder path, List<FieldProblem> problems) {
        int length = path.length();
        if (node instanceof ObjectNode object) {
            List<String> nulls = null;
            for (Map.Entry<String, JsonNode> member : object.properties()) {
                JsonNode value = member.getValue();
                if (value.isNull() || value.isContainer()) {
                    path.append(length > 0 ? "." : "").append(member.getKey());
                    if (value.isNull()) {
                        (nulls != null ? nulls : (nulls = new ArrayList<>())).add(member.getKey());
                        problems.add(new FieldProblem(path.toString(), "must not be null; leave the field out for its default"));
                    } else {
                        dropNullFields(value, path, problems);
                    }
                    path.setLength(length);
                }
            }
            if (nulls != null) {
                nulls.forEach(object::remove);
            }
        } else if (node.isArray()) {
            for (int i = 0; i < node.size(); i++) {
                if (node.get(i).isContainer()) {
                    dropNullFields(node.get(i), path.append('[').append(i).append(']'), problems);
                    path.setLength(length);
                }
            }
        }
    }

    /**
     * The null-field problems and the others, sorted by field; a field that another rule names (a
     * required one: "objects", "type") keeps that rule's message instead of the null one.
     */
    private static List<FieldProblem> withNulls(List<FieldProblem> nulls, List<FieldProblem> others) {
        List<FieldProblem> all = new ArrayList<>(others);
        for (FieldProblem n : nulls) {
            if (others.stream().noneMatch(o -> o.field().equals(n.field()))) {
                all.add(n);
            }
        }
        all.sort(Comparator.comparing(FieldProblem::field).thenComparing(FieldProblem::message));
        return all;
    }

    private static void applyOverrides(ObjectNode root, Map<String, Object> overrides) {
        for (Map.Entry<String, Object> override : overrides.entrySet()) {
            String[] parts = override.getKey().split("\\.");
            ObjectNode node = root;
            for (int i = 0; i < parts.length - 1; i++) {
                JsonNode child = node.get(parts[i]);
                if (child == null || child.isNull()) {
                    child = node.putObject(parts[i]);
                }
                if (!child.isObject()) {
                    node = null;
                    break;
                }
                node = (ObjectNode) child;
            }
            if (node != null) {
                node.set(parts[parts.length - 1], valueNode(override.getValue()));
            }
        }
    }

    private static JsonNode valueNode(Object value) {
        JsonNodeFactory f = JsonNodeFactory.instance;
        if (value instanceof Integer i) {
            return f.numberNode(i);
        }
        if (value instanceof Long l) {
            return f.numberNode(l);
        }
        if (value instanceof Double d) {
            return f.numberNode(d);
        }
        return f.textNode(String.valueOf(value));
    }

    /** A Bean Validation path as a JSON path: objects[2].center[1]. */
    static String pathOf(Path path) {
        StringBuilder sb = new StringBuilder();
        for (Path.Node node : path) {
            if (node.isInIterable()) {
                sb.append('[').append(node.getIndex() != null ? node.getIndex() : node.getKey()).append(']');
            }
            if (node.getKind() == ElementKind.PROPERTY && node.getName() != null) {
                if (sb.length() > 0) {
                    sb.append('.');
                }
                sb.append(node.getName());
            }
        }
        return sb.toString();
    }

    /** A Jackson path as a JSON path. */
    static String pathOf(List<JacksonException.Reference> references) {
        StringBuilder sb = new StringBuilder();
        for (JacksonException.Reference ref : references) {
            if (ref.getPropertyName() != null) {
                if (sb.length() > 0) {
                    sb.append('.');
                }
                sb.append(ref.getPropertyName());
            } else if (ref.getIndex() >= 0) {
                sb.append('[').append(ref.getIndex()).append(']');
            }
        }
        return sb.toString();
    }

    static FieldProblem problemOf(JacksonException e) {
        String path = pathOf(e.getPath());
        if (e instanceof InvalidTypeIdException typeId) {
            String field = path.isEmpty() ? "type" : path + ".type";
            String known = knownTypes(typeId.getBaseType().getRawClass());
            return typeId.getTypeId() == null
                    ? new FieldProblem(field, "is required: one of " + known)
                    : new FieldProblem(field, "unknown type '" + typeId.getTypeId() + "'; must be one of " + known);
        }
        if (e instanceof UnrecognizedPropertyException unknown) {
            List<String> known = unknown.getKnownPropertyIds().stream().map(String::valueOf).sorted().toList();
            return new FieldProblem(path, "is not a field here; known fields: " + String.join(", ", known));
        }
        if (e instanceof InputCoercionException coercion && wholeNumberRange(coercion.getTargetType()) != null) {
            return new FieldProblem(path, "must be a whole number " + wholeNumberRange(coercion.getTargetType()));
        }
        if (e instanceof MismatchedInputException mismatch && mismatch.getTargetType() != null) {
            return new FieldProblem(path, expected(mismatch.getTargetType()));
        }
        return new FieldProblem(path, ParserMessages.plain(firstLine(e.getOriginalMessage())));
    }

    /** "from MIN to MAX" for an integer type, else null. */
    private static String wholeNumberRange(Class<?> type) {
        if (type == Integer.class || type == int.class) {
            return "from " + Integer.MIN_VALUE + " to " + Integer.MAX_VALUE;
        }
        if (type == Long.class || type == long.class) {
            return "from " + Long.MIN_VALUE + " to " + Long.MAX_VALUE;
        }
        return null;
    }

    private static String expected(Class<?> type) {
        if (type == Double.class || type == double.class) {
            return "must be a number";
        }
        if (type == Integer.class || type == int.class || type == Long.class || type == long.class) {
            return "must be a whole number";
        }
        if (type == Boolean.class || type == boolean.class) {
            return "must be true or false";
        }
        if (type == String.class) {
            return "must be a string";
        }
        if (List.class.isAssignableFrom(type)) {
            return "must be an array";
        }
        return "must be a JSON object";
    }

    private static String knownTypes(Class<?> base) {
        JsonSubTypes subTypes = base.getAnnotation(JsonSubTypes.class);
        if (subTypes == null) {
            return "?";
        }
        return Arrays.stream(subTypes.value()).map(JsonSubTypes.Type::name).collect(Collectors.joining(", "));
    }

    /** The first line of a parser message, without Jackson's source-location trailer. */
    private static String firstLine(String message) {
        if (message == null) {
            return "unreadable";
        }
        int nl = message.indexOf('\n');
        String line = nl < 0 ? message : message.substring(0, nl);
        return line.replaceAll("\\s*\\(start marker at .*$", "").replaceAll("\\s*at \\[Source.*$", "");
    }
}
