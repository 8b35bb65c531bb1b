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

/** A 3-vector in JSON: an array of exactly three numbers [x, y, z]. Null (absent) is valid. */
@Documented
@Constraint(validatedBy = Vector.Validator.class)
@Target({ElementType.FIELD, ElementType.METHOD, ElementType.PARAMETER, ElementType.RECORD_COMPONENT})
@Retention(RetentionPolicy.RUNTIME)
public @interface Vector {

    String message() default "must be an array of three numbers [x, y, z]";

    Class<?>[] groups() default {};

    Class<? extends Payload>[] payload() default {};

    final class Validator implements ConstraintValidator<Vector, List<Double>> {
        @Override
        public boolean isValid(List<Double> value, ConstraintValidatorContext context) {
            return value == null || value.size() == 3;
        }
    }
}
