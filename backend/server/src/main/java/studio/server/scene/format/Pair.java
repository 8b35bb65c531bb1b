package studio.server.scene.format;

import java.lang.annotation.Documented;
import java.lang.annotation.ElementType;
import java.lang.annotation.Retention;
import java.lang.annotation.RetentionPolicy;
import java.lang.annotation.Target;
import java.util.List;

import jakarta.validation.Constraint;
import jakarta.validation.ConstraintValidator;
import jakarta.validation.ConstraintValidatorContext;
import jakarta.validation.Payload;

/** A 2-vector in JSON (a width and a height): an array of exactly two numbers [w, h]. Null (absent) is valid. */
@Documented
@Constraint(validatedBy = Pair.Validator.class)
@Target({ElementType.FIELD, ElementType.METHOD, ElementType.PARAMETER, ElementType.RECORD_COMPONENT})
@Retention(RetentionPolicy.RUNTIME)
public @interface Pair {

    String message() default "must be an array of two numbers [w, h]";

    Class<?>[] groups() default {};

    Class<? extends Payload>[] payload() default {};

    final class Validator implements ConstraintValidator<Pair, List<Double>> {
        @Override
        public boolean isValid(List<Double> value, ConstraintValidatorContext context) {
            return value == null || value.size() == 2;
        }
    }
}
