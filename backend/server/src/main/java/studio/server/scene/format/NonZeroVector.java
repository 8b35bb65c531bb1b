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

/** A direction: a vector with at least one non-zero component. Null and malformed vectors are left to other rules. */
@Documented
@Constraint(validatedBy = NonZeroVector.Validator.class)
@Target({ElementType.FIELD, ElementType.METHOD, ElementType.PARAMETER, ElementType.RECORD_COMPONENT})
@Retention(RetentionPolicy.RUNTIME)
public @interface NonZeroVector {

    String message() default "must not be a zero-length vector";

    Class<?>[] groups() default {};

    Class<? extends Payload>[] payload() default {};

    final class Validator implements ConstraintValidator<NonZeroVector, List<Double>> {
        @Override
        public boolean isValid(List<Double> value, ConstraintValidatorContext context) {
            if (value == null || value.size() != 3 || value.contains(null)) {
                return true;
            }
            return value.stream().anyMatch(v -> v != 0);
        }
    }
}
