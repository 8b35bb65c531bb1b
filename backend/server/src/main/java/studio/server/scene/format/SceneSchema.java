package studio.server.scene.format;

import java.lang.annotation.Annotation;
import java.lang.reflect.AnnotatedElement;
import java.lang.reflect.AnnotatedParameterizedType;
import java.lang.reflect.AnnotatedType;
import java.lang.reflect.Field;
import java.lang.reflect.ParameterizedType;
import java.lang.reflect.RecordComponent;
import java.lang.reflect.Type;
import java.math.BigDecimal;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.stream.IntStream;

import org.hibernate.validator.constraints.CodePointLength;

import com.fasterxml.jackson.annotation.JsonSubTypes;

import jakarta.validation.constraints.DecimalMax;
import jakarta.validation.constraints.DecimalMin;
import jakarta.validation.constraints.Max;
import jakarta.validation.constraints.Min;
import jakarta.validation.constraints.NotNull;
import jakarta.validation.constraints.Pattern;
import jakarta.validation.constraints.Positive;
import jakarta.validation.constraints.PositiveOrZero;

/**
 * The scene format as a JSON Schema (draft 2020-12), derived from the DTO records and their
 * Bean Validation annotations, with this server's limits as maximum and maxItems and each field's
 * default ({@link SceneDefaults#of}). It is what the server enforces, so the editor's types and
 * defaults are checked against it and cannot drift.
 */
public final class SceneSchema {

    private final SceneLimits limits;
    private final Map<String, Object> defs = new LinkedHashMap<>();

    private SceneSchema(SceneLimits limits) {
        this.limits = limits;
    }

    /** The schema as nested maps and lists, ready for any JSON writer. */
    public static Map<String, Object> of(SceneLimits limits) {
        SceneSchema schema = new SceneSchema(limits);
        Map<String, Object> root = new LinkedHashMap<>();
        root.put("$schema", "https://json-schema.org/draft/2020-12/schema");
        root.put("title", "Ray Studio scene");
        root.putAll(schema.record(SceneDto.class, null, ""));
        root.put("$defs", schema.defs);
        return root;
    }

    private Map<String, Object> record(Class<?> type, String typeId, String path) {
        Map<String, Object> properties = new LinkedHashMap<>();
        List<String> required = new ArrayList<>();
        if (typeId != null) {
            properties.put("type", Map.of("const", typeId));
            required.add("type");
        }
        for (RecordComponent component : type.getRecordComponents()) {
            Field field = field(type, component.getName());
            String childPath = path.isEmpty() ? component.getName() : path + "." + component.getName();
            Map<String, Object> property = value(component.getGenericType(), field.getAnnotatedType(), field, childPath);
            Object fallback = SceneDefaults.of(type, component.getName());
            if (fallback != null) {
                property.put("default", fallback);
            }
            properties.put(component.getName(), property);
            if (field.isAnnotationPresent(NotNull.class)) {
                required.add(component.getName());
            }
        }
        Map<String, Object> schema = new LinkedHashMap<>();
        schema.put("type", "object");
        schema.put("properties", properties);
        if (!required.isEmpty()) {
            schema.put("required", required);
        }
        schema.put("additionalProperties", false);
        crossFieldRules(type, schema);
        return schema;
    }

    /**
     * The rules across fields that SceneMapper checks and JSON Schema can state too (the others, such
     * as a camera's up along its view direction, are listed in the API's agreement test).
     */
    private void crossFieldRules(Class<?> type, Map<String, Object> schema) {
        if (type == ObjectDto.Mesh.class) {
            // the OBJ text inline, a file name or an asset id: one of them
            schema.put("oneOf", List.of(Map.of("required", List.of("obj")), Map.of("required", List.of("file")),
                    Map.of("required", List.of("asset"))));
        }
        if (type == ObjectDto.Gltf.class) {
            // a file name or an asset id: one of them
            schema.put("oneOf", List.of(Map.of("required", List.of("file")), Map.of("required", List.of("asset"))));
        }
        if (type == RenderDto.class) {
            // the regular sampler needs a square number of samples, and cannot sample adaptively
            List<Integer> squares = IntStream.rangeClosed(1, (int) Math.sqrt(limits.maxSamples()))
                    .map(k -> k * k).boxed().toList();
            Map<String, Object> regular = new LinkedHashMap<>();
            regular.put("properties", Map.of("sampler", Map.of("const", "regular")));
            regular.put("required", List.of("sampler"));
            Map<String, Object> then = new LinkedHashMap<>();
            then.put("samples", Map.of("enum", squares));
            then.put("adaptive", Map.of("maximum", 0));
            schema.put("if", regular);
            schema.put("then", Map.of("properties", then));
        }
    }

    private Map<String, Object> value(Type type, AnnotatedType annotated, AnnotatedElement element, String path) {
        Class<?> raw = type instanceof ParameterizedType p ? (Class<?>) p.getRawType() : (Class<?>) type;
        Map<String, Object> schema = new LinkedHashMap<>();
        if (raw == Double.class) {
            schema.put("type", "number");
            numberBounds(schema, element, false);
        } else if (raw == Integer.class || raw == Long.class) {
            schema.put("type", "integer");
            numberBounds(schema, element, true);
            Integer limit = limitOf(path);
            if (limit != null) {
                schema.put("maximum", limit);
            }
            // what the Java type holds: a larger whole number is refused ("must be a whole number from ... to ...")
            schema.putIfAbsent("minimum", raw == Long.class ? (Object) Long.MIN_VALUE : (Object) Integer.MIN_VALUE);
            schema.putIfAbsent("maximum", raw == Long.class ? (Object) Long.MAX_VALUE : (Object) Integer.MAX_VALUE);
        } else if (raw == Boolean.class) {
            schema.put("type", "boolean");
        } else if (raw == String.class) {
            schema.put("type", "string");
            Pattern pattern = annotation(element, Pattern.class);
            if (pattern != null) {
                schema.put("pattern", "^(" + pattern.regexp() + ")$");
            }
            CodePointLength length = annotation(element, CodePointLength.class);
            if (length != null) {
                schema.put("maxLength", length.max());
            }
        } else if (raw == List.class) {
            AnnotatedType item = ((AnnotatedParameterizedType) annotated).getAnnotatedActualTypeArguments()[0];
            schema.put("type", "array");
            schema.put("items", value(item.getType(), item, item, path + "[]"));
            if (element.isAnnotationPresent(Vector.class)) {
                schema.put("minItems", 3);
                schema.put("maxItems", 3);
            }
            if (element.isAnnotationPresent(NonZeroVector.class)) {
                schema.put("not", Map.of("items", Map.of("const", 0)));
            }
            Integer limit = limitOf(path);
            if (limit != null) {
                schema.put("maxItems", limit);
            }
        } else if (raw.isRecord()) {
            String name = raw.getSimpleName().replaceAll("Dto$", "");
            defs.computeIfAbsent(name, n -> record(raw, null, path));
            schema.put("$ref", "#/$defs/" + name);
        } else if (raw.isInterface() && raw.isAnnotationPresent(JsonSubTypes.class)) {
            String family = raw.getSimpleName().replaceAll("Dto$", "");
            if (!defs.containsKey(family)) {
                defs.put(family, Map.of()); // reserve the name
                List<Object> oneOf = new ArrayList<>();
                for (JsonSubTypes.Type sub : raw.getAnnotation(JsonSubTypes.class).value()) {
                    String name = capitalise(sub.name()) + family;
                    defs.put(name, record(sub.value(), sub.name(), path));
                    oneOf.add(Map.of("$ref", "#/$defs/" + name));
                }
                defs.put(family, Map.of("oneOf", oneOf));
            }
            schema.put("$ref", "#/$defs/" + family);
        } else {
            throw new IllegalStateException("no schema for " + type + " at " + path);
        }
        return schema;
    }

    private void numberBounds(Map<String, Object> schema, AnnotatedElement element, boolean integer) {
        if (element.isAnnotationPresent(Positive.class)) {
            if (integer) {
                schema.put("minimum", 1);
            } else {
                schema.put("exclusiveMinimum", 0);
            }
        }
        if (element.isAnnotationPresent(PositiveOrZero.class)) {
            schema.put("minimum", 0);
        }
        Min min = annotation(element, Min.class);
        if (min != null) {
            schema.put("minimum", min.value());
        }
        Max max = annotation(element, Max.class);
        if (max != null) {
            schema.put("maximum", max.value());
        }
        DecimalMin decimalMin = annotation(element, DecimalMin.class);
        if (decimalMin != null) {
            schema.put(decimalMin.inclusive() ? "minimum" : "exclusiveMinimum", number(decimalMin.value()));
        }
        DecimalMax decimalMax = annotation(element, DecimalMax.class);
        if (decimalMax != null) {
            schema.put(decimalMax.inclusive() ? "maximum" : "exclusiveMaximum", number(decimalMax.value()));
        }
    }

    /** This server's configured limit for the field at a path, if it has one. */
    private Integer limitOf(String path) {
        return switch (path) {
            case "image.width" -> limits.maxWidth();
            case "image.height" -> limits.maxHeight();
            case "render.samples" -> limits.maxSamples();
            case "render.maxDepth" -> limits.maxDepth();
            case "objects" -> limits.maxObjects();
            case "lights" -> limits.maxLights();
            default -> null;
        };
    }

    private static Number number(String decimal) {
        BigDecimal value = new BigDecimal(decimal);
        if (value.stripTrailingZeros().scale() <= 0 && value.abs().compareTo(BigDecimal.valueOf(Integer.MAX_VALUE)) < 0) {
            return value.intValueExact();
        }
        // a whole bound past int (the coordinates' 1e12) as a whole number, as the OpenAPI document writes it
        return value.stripTrailingZeros().scale() <= 0 && value.abs().compareTo(BigDecimal.valueOf(Long.MAX_VALUE)) < 0
                ? (Number) value.longValueExact() : (Number) value.doubleValue();
    }

    private static <A extends Annotation> A annotation(AnnotatedElement element, Class<A> type) {
        return element.getAnnotation(type);
    }

    private static Field field(Class<?> type, String name) {
        try {
            return type.getDeclaredField(name);
        } catch (NoSuchFieldException e) {
            throw new IllegalStateException(e);
        }
    }

    private static String capitalise(String s) {
        return Character.toUpperCase(s.charAt(0)) + s.substring(1);
    }
}
