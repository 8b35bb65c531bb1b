package studio.server.scene.reading;

import java.lang.annotation.Annotation;
import java.lang.reflect.AnnotatedParameterizedType;
import java.lang.reflect.Field;
import java.lang.reflect.ParameterizedType;
import java.lang.reflect.RecordComponent;
import java.lang.reflect.Type;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeSet;

import com.fasterxml.jackson.annotation.JsonSubTypes;
import com.fasterxml.jackson.annotation.JsonTypeInfo;

/**
 * Writes {@link SceneConstraints}' source from the scene records' annotations: builds a
 * {@link FastPathBinder} over them that asks these annotations for each field's rules and each
 * polymorphic type's kinds and each record's constructor, and writes down every answer, so the
 * table holds exactly what the binder asks for.
 */
final class SceneConstraintsSource implements FastPathBinder.Constraints {

    private final Map<String, List<FieldRule>> rules = new LinkedHashMap<>();
    private final Map<Class<?>, SceneConstraints.Subtypes> subtypes = new LinkedHashMap<>();
    /** The records the binder makes, in the order it first asks. */
    private final Set<Class<?>> records = new LinkedHashSet<>();
    private final Set<String> imports = new TreeSet<>();

    private SceneConstraintsSource() {
    }

    /** The rules and kinds the annotations state for the records a binder of {@code root} reads. */
    static SceneConstraintsSource of(Class<?> root) {
        SceneConstraintsSource source = new SceneConstraintsSource();
        new FastPathBinder(root, source);
        return source;
    }

    Map<String, List<FieldRule>> rules() {
        return rules;
    }

    Map<Class<?>, SceneConstraints.Subtypes> subtypes() {
        return subtypes;
    }

    /** A field's constraints on the field and its type; a list's elements' on its type argument. */
    @Override
    public List<FieldRule> rulesOf(Class<?> record, RecordComponent component, boolean elements) {
        String key = FastPathBinder.keyOf(record, component, elements);
        Field field;
        try {
            field = record.getDeclaredField(component.getName());
        } catch (NoSuchFieldException e) {
            throw new IllegalStateException(e);
        }
        List<Annotation> annotations = new ArrayList<>();
        if (elements) {
            // the binder asks only of a List<E> with a plain class E
            AnnotatedParameterizedType list = (AnnotatedParameterizedType) field.getAnnotatedType();
            annotations.addAll(List.of(list.getAnnotatedActualTypeArguments()[0].getAnnotations()));
        } else {
            annotations.addAll(List.of(field.getAnnotations()));
            annotations.addAll(List.of(field.getAnnotatedType().getAnnotations()));
        }
        List<FieldRule> found = rulesOf(annotations, key);
        rules.put(key, found);
        return found;
    }

    /** A sealed interface Jackson reads by a type name in a property; null for any other type. */
    @Override
    public SceneConstraints.Subtypes subtypesOf(Class<?> type) {
        JsonTypeInfo info = type.getAnnotation(JsonTypeInfo.class);
        JsonSubTypes types = type.getAnnotation(JsonSubTypes.class);
        if (!type.isInterface() || info == null || info.use() != JsonTypeInfo.Id.NAME
                || info.include() != JsonTypeInfo.As.PROPERTY || types == null) {
            return null;
        }
        Map<String, Class<?>> byName = new LinkedHashMap<>();
        for (JsonSubTypes.Type sub : types.value()) {
            byName.put(sub.name(), sub.value());
        }
        SceneConstraints.Subtypes found = new SceneConstraints.Subtypes(info.property(), byName);
        subtypes.put(type, found);
        return found;
    }

    /** Notes a record the binder makes, for the table's constructor calls; this binder binds nothing. */
    @Override
    public FastPathBinder.RecordMaker makerOf(Class<?> type) {
        records.add(type);
        return values -> {
            throw new UnsupportedOperationException("the table's writer only notes what the binder asks for");
        };
    }

    /** The distinct rules, in order (a constraint that may sit on a field and a type use is on both). */
    private static List<FieldRule> rulesOf(List<Annotation> annotations, String where) {
        Set<FieldRule> out = new LinkedHashSet<>();
        for (Annotation annotation : annotations) {
            FieldRule rule = FieldRule.of(annotation, where);
            if (rule != null) {
                out.add(rule);
            }
        }
        return List.copyOf(out);
    }

    /** The Java source of {@code SceneConstraints}. */
    String javaSource() {
        StringBuilder body = new StringBuilder();
        body.append("    static final Map<String, List<FieldRule>> RULES = Map.ofEntries(\n");
        int n = 0;
        for (Map.Entry<String, List<FieldRule>> e : rules.entrySet()) {
            List<String> items = new ArrayList<>();
            for (FieldRule rule : e.getValue()) {
                items.add(javaOf(rule));
            }
            String line = "            entry(" + literal(e.getKey()) + ", List.of(" + String.join(", ", items) + "))";
            if (line.length() > 118) {
                line = "            entry(" + literal(e.getKey()) + ", List.of(\n                    "
                        + String.join(",\n                    ", items) + "))";
            }
            body.append(line).append(++n < rules.size() ? ",\n" : ");\n");
        }
        body.append("\n    static final Map<Class<?>, Subtypes> SUBTYPES = Map.ofEntries(\n");
        n = 0;
        for (Map.Entry<Class<?>, SceneConstraints.Subtypes> e : subtypes.entrySet()) {
            body.append("            entry(").append(classLiteral(e.getKey())).append(", new Subtypes(")
                    .append(literal(e.getValue().property())).append(", Map.ofEntries(\n");
            int m = 0;
            for (Map.Entry<String, Class<?>> sub : e.getValue().byName().entrySet()) {
                body.append("                    entry(").append(literal(sub.getKey())).append(", ")
                        .append(classLiteral(sub.getValue())).append(")")
                        .append(++m < e.getValue().byName().size() ? ",\n" : ")))");
            }
            body.append(++n < subtypes.size() ? ",\n" : ");\n");
        }
        body.append("""

                    /** A record of {@code type} from its components' values, in declaration order. */
                    @SuppressWarnings("unchecked")
                    static Object make(Class<?> type, Object[] v) {
                """);
        for (Class<?> record : records) {
            List<String> args = new ArrayList<>();
            RecordComponent[] components = record.getRecordComponents();
            for (int i = 0; i < components.length; i++) {
                args.add("(" + sourceName(components[i].getGenericType()) + ") v[" + i + "]");
            }
            String call = "return new " + FastPathBinder.keyOf(record) + "(";
            String oneLine = "            " + call + String.join(", ", args) + ");";
            body.append("        if (type == ").append(classLiteral(record)).append(") {\n")
                    .append(oneLine.length() <= 120 ? oneLine
                            : "            " + call + "\n                    " + String.join(",\n                    ", args) + ");")
                    .append("\n        }\n");
        }
        body.append("        throw new IllegalArgumentException(\"no record the fast path reads: \" + type.getName());\n    }\n");
        StringBuilder out = new StringBuilder();
        out.append("package studio.server.scene.reading;\n\n");
        out.append("import static java.util.Map.entry;\n\n");
        out.append("import java.util.List;\nimport java.util.Map;\n\n");
        for (String name : imports) {
            out.append("import ").append(name).append(";\n");
        }
        out.append("""

                /**
                 * Generated from the scene records' annotations by SceneConstraintsTest, which fails when this
                 * file differs from what it would write; regenerate it rather than edit it:
                 * {@code mvn -f backend/pom.xml -pl engine,server test -Dtest=SceneConstraintsTest
                 * -Dsurefire.failIfNoSpecifiedTests=false -Dscene-constraints.write=true}.
                 *
                 * <p>The constraints {@link FastPathBinder} checks, as data: per record field ("Type.field", and
                 * "Type.field[]" for a list's elements) the rules its annotations state, and per polymorphic
                 * type its type property and kinds; and each record's constructor, called directly.
                 */
                final class SceneConstraints {

                    private SceneConstraints() {
                    }

                    /** A polymorphic type: the JSON property that names the kind, and each kind's record. */
                    record Subtypes(String property, Map<String, Class<?>> byName) {
                    }

                """);
        out.append(body);
        out.append("}\n");
        return out.toString();
    }

    private String classLiteral(Class<?> type) {
        Class<?> top = type;
        while (top.getEnclosingClass() != null) {
            top = top.getEnclosingClass();
        }
        imports.add(top.getName());
        return FastPathBinder.keyOf(type) + ".class";
    }

    /** A component's type as the source spells it: {@code Double}, {@code List<ObjectDto>}. */
    private String sourceName(Type type) {
        if (type instanceof Class<?> plain) {
            return plain.getPackageName().equals("java.lang") ? plain.getSimpleName() : classLiteral(plain).replace(".class", "");
        }
        if (type instanceof ParameterizedType generic && generic.getRawType() == List.class) {
            return "List<" + sourceName(generic.getActualTypeArguments()[0]) + ">";
        }
        throw new IllegalStateException("the generated table cannot name the type " + type.getTypeName());
    }

    /** {@code new FieldRule.Min(1L)}: the rule's record built from its components. */
    private static String javaOf(FieldRule rule) {
        List<String> args = new ArrayList<>();
        for (RecordComponent component : rule.getClass().getRecordComponents()) {
            Object value;
            try {
                value = component.getAccessor().invoke(rule);
            } catch (ReflectiveOperationException e) {
                throw new IllegalStateException(e);
            }
            args.add(value instanceof String s ? literal(s) : value instanceof Long l ? l + "L" : String.valueOf(value));
        }
        return "new FieldRule." + rule.getClass().getSimpleName() + "(" + String.join(", ", args) + ")";
    }

    private static String literal(String text) {
        StringBuilder out = new StringBuilder("\"");
        for (char c : text.toCharArray()) {
            switch (c) {
                case '"' -> out.append("\\\"");
                case '\\' -> out.append("\\\\");
                case '\n' -> out.append("\\n");
                default -> {
                    if (c < 0x20 || c > 0x7e) {
                        out.append(String.format("\\u%04x", (int) c));
                    } else {
                        out.append(c);
                    }
                }
            }
        }
        return out.append('"').toString();
    }
}
