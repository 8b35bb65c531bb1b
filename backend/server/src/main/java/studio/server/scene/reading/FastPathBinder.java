package studio.server.scene.reading;

import java.lang.reflect.ParameterizedType;
import java.lang.reflect.RecordComponent;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.function.Function;
import java.util.function.Predicate;

import tools.jackson.databind.JsonNode;
import tools.jackson.databind.node.ObjectNode;

/**
 * The fast path of {@link SceneReader}: binds a scene tree straight to its records when every value
 * is plainly valid, checking the records' Bean Validation constraints as {@link SceneConstraints}
 * lists them (generated from the annotations, which it never reads itself). It
 * gives no messages: anything it is not sure of (an unknown field, a value of another JSON type, a
 * broken rule, a null) makes it answer null, and the scene takes the full path (Jackson binding and
 * Hibernate Validator), which names every problem. So it may only ever be stricter than the full
 * path, never looser: {@code FastPathBinderTest} checks that on every example scene and on
 * thousands of mutated ones, and that it returns the same records. It makes the records through
 * their constructors as {@link SceneConstraints} calls them, not by reflection, whose first call of
 * each record's constructor (method handles spun at run time) took most of a cold binding.
 *
 * <p>Why: Jackson's data binding and Hibernate Validator take a large share of a cold command-line
 * render of a large scene, and of a warm read of one ({@code SceneTreeBench} in the server's tests).
 *
 * <p>It knows the constraints the scene records use ({@link FieldRule}): a record field with any
 * other constraint fails {@code SceneConstraintsTest}, which also fails when the table is out of date
 * with the annotations, and a field missing from the table fails construction. So a new rule cannot
 * be skipped silently.
 */
final class FastPathBinder {

    /** Thrown (without a stack trace) to leave for the full path. */
    private static final class NotSure extends RuntimeException {
        private static final NotSure INSTANCE = new NotSure();

        private NotSure() {
            super(null, null, false, false);
        }
    }

    /** Reads one JSON value as a Java value, or throws {@link NotSure}. */
    private interface Reader {
        Object read(JsonNode node);
    }

    /**
     * Where the binder finds the rules of a record's field, or of its elements for a list (null:
     * none are known, which fails construction), and the kinds of a polymorphic type (null: it is
     * not one). At run time {@link #GENERATED}; {@code SceneConstraintsTest} walks the records
     * through the binder with the annotations instead, and writes down what it was asked.
     */
    interface Constraints {
        List<FieldRule> rulesOf(Class<?> record, RecordComponent component, boolean elements);

        SceneConstraints.Subtypes subtypesOf(Class<?> type);

        /** How a record of {@code type} is made from its components' values, in declaration order. */
        RecordMaker makerOf(Class<?> type);
    }

    /** A record's canonical constructor. */
    interface RecordMaker {
        Object make(Object[] values);
    }

    /** The rules and kinds as {@link SceneConstraints} lists them. */
    static final Constraints GENERATED = new Constraints() {
        @Override
        public List<FieldRule> rulesOf(Class<?> record, RecordComponent component, boolean elements) {
            return SceneConstraints.RULES.get(keyOf(record, component, elements));
        }

        @Override
        public SceneConstraints.Subtypes subtypesOf(Class<?> type) {
            return SceneConstraints.SUBTYPES.get(type);
        }

        @Override
        public RecordMaker makerOf(Class<?> type) {
            return values -> SceneConstraints.make(type, values);
        }
    };

    private final Constraints constraints;
    /** The readers made so far, by type (each type is read by one reader). */
    private final Map<Class<?>, Reader> known = new HashMap<>();
    private final Reader root;

    FastPathBinder(Class<?> rootType) {
        this(rootType, GENERATED);
    }

    FastPathBinder(Class<?> rootType, Constraints constraints) {
        this.constraints = constraints;
        this.root = readerOf(rootType);
    }

    /** The records bound from {@code tree}, all constraints holding, or null: take the full path. */
    @SuppressWarnings("unchecked")
    <T> T bind(JsonNode tree) {
        try {
            return (T) root.read(tree);
        } catch (NotSure e) {
            return null;
        }
    }

    private static NotSure notSure() {
        return NotSure.INSTANCE;
    }

    /**
     * The JSON values a boxed field takes as Jackson reads it here: no coercion, a whole number for
     * Integer and Long (Integer within int's range), any number for Double.
     */
    private static final Map<Class<?>, Reader> SCALARS = Map.of(
            Double.class, scalar(node -> node.isInt() || node.isLong() || node.isDouble(), JsonNode::doubleValue),
            Integer.class, scalar(JsonNode::isInt, JsonNode::intValue),
            Long.class, scalar(node -> node.isInt() || node.isLong(), JsonNode::longValue),
            Boolean.class, scalar(JsonNode::isBoolean, JsonNode::booleanValue),
            String.class, scalar(JsonNode::isString, JsonNode::stringValue));

    private static Reader scalar(Predicate<JsonNode> kind, Function<JsonNode, Object> value) {
        return node -> {
            if (!kind.test(node)) {
                throw notSure();
            }
            return value.apply(node);
        };
    }

    private Reader readerOf(Class<?> type) {
        Reader scalar = SCALARS.get(type);
        if (scalar != null) {
            return scalar;
        }
        Reader done = known.get(type);
        if (done != null) {
            return done;
        }
        if (type.isRecord()) {
            RecordReader reader = new RecordReader(type, null);
            known.put(type, reader);
            reader.complete();
            return reader;
        }
        SceneConstraints.Subtypes subtypes = constraints.subtypesOf(type);
        if (subtypes == null) {
            throw new IllegalStateException("the fast path cannot read " + type.getName());
        }
        String property = subtypes.property();
        Map<String, RecordReader> byName = new HashMap<>();
        for (Map.Entry<String, Class<?>> sub : subtypes.byName().entrySet()) {
            RecordReader reader = new RecordReader(sub.getValue(), property);
            byName.put(sub.getKey(), reader);
            reader.complete();
        }
        Reader polymorphic = node -> {
            JsonNode id = node.get(property);
            RecordReader reader = id != null && id.isString() ? byName.get(id.stringValue()) : null;
            if (reader == null) {
                throw notSure();
            }
            return reader.read(node);
        };
        known.put(type, polymorphic);
        return polymorphic;
    }

    /** A record type's name in {@link SceneConstraints}: {@code ObjectDto.Sphere}. */
    static String keyOf(Class<?> type) {
        return type.getName().substring(type.getPackageName().length() + 1).replace('$', '.');
    }

    /** A field's name in {@link SceneConstraints}: {@code ObjectDto.Sphere.center}, with "[]" for its elements. */
    static String keyOf(Class<?> record, RecordComponent component, boolean elements) {
        return keyOf(record) + "." + component.getName() + (elements ? "[]" : "");
    }

    /** A record from a JSON object: every member must be one of its components (or the type id). */
    private final class RecordReader implements Reader {
        private final Class<?> type;
        private final String typeProperty;
        private final Map<String, Integer> index = new HashMap<>();
        private Reader[] readers;
        private Predicate<Object>[] checks;
        private RecordMaker maker;

        RecordReader(Class<?> type, String typeProperty) {
            if (!type.isRecord()) {
                throw new IllegalStateException("the fast path reads records only, not " + type.getName());
            }
            this.type = type;
            this.typeProperty = typeProperty;
        }

        @SuppressWarnings("unchecked")
        void complete() {
            RecordComponent[] components = type.getRecordComponents();
            readers = new Reader[components.length];
            checks = new Predicate[components.length];
            for (int i = 0; i < components.length; i++) {
                RecordComponent component = components[i];
                index.put(component.getName(), i);
                checks[i] = checkOf(type, component, false);
                readers[i] = List.class.isAssignableFrom(component.getType())
                        ? listReader(type, component) : readerOf(component.getType());
            }
            maker = constraints.makerOf(type);
        }

        @Override
        public Object read(JsonNode node) {
            if (!(node instanceof ObjectNode object)) {
                throw notSure();
            }
            Object[] values = new Object[readers.length];
            for (Map.Entry<String, JsonNode> member : object.properties()) {
                String name = member.getKey();
                if (name.equals(typeProperty)) {
                    continue;
                }
                Integer i = index.get(name);
                if (i == null) {
                    throw notSure();
                }
                values[i] = readers[i].read(member.getValue());
            }
            for (int i = 0; i < values.length; i++) {
                if (!checks[i].test(values[i])) {
                    throw notSure();
                }
            }
            try {
                return maker.make(values);
            } catch (RuntimeException refused) {
                throw notSure(); // a constructor that refuses its values: the full path names why
            }
        }
    }

    /** A list from a JSON array; its elements have rules of their own. */
    private Reader listReader(Class<?> record, RecordComponent component) {
        if (!(component.getGenericType() instanceof ParameterizedType parameterized)
                || !(parameterized.getActualTypeArguments()[0] instanceof Class<?> elementType)) {
            throw new IllegalStateException("the fast path needs a plain element type at "
                    + keyOf(record, component, false));
        }
        Predicate<Object> elementCheck = checkOf(record, component, true);
        Reader elementReader = readerOf(elementType);
        return node -> {
            if (!node.isArray()) {
                throw notSure();
            }
            List<Object> list = new ArrayList<>(node.size());
            for (JsonNode item : node) {
                Object value = item.isNull() ? null : elementReader.read(item);
                if (!elementCheck.test(value)) {
                    throw notSure();
                }
                list.add(value);
            }
            return list;
        };
    }

    /** All the rules of a field (or of a list's elements), as one test. */
    private Predicate<Object> checkOf(Class<?> record, RecordComponent component, boolean elements) {
        List<FieldRule> rules = constraints.rulesOf(record, component, elements);
        if (rules == null) {
            throw new IllegalStateException("SceneConstraints has no rules for " + keyOf(record, component, elements)
                    + ": regenerate it (the command is in its class comment)");
        }
        Predicate<Object> all = value -> true;
        for (FieldRule rule : rules) {
            all = all.and(rule.check());
        }
        return all;
    }
}
