package studio.server.scene.compiling;

import static studio.server.scene.compiling.FormatValues.or;
import static studio.server.scene.compiling.FormatValues.vec;

import java.util.ArrayList;
import java.util.List;

import studio.engine.light.PointLight;
import studio.server.scene.format.LightDto;
import studio.server.scene.format.SceneDefaults;
import studio.server.scene.format.SceneLimits;

/** The lights: the default light when a scene has no "lights" field, none for an empty list. */
final class LightMapping {

    private LightMapping() {
    }

    /** The lights up to the server's limit (and a problem for the rest). */
    static List<PointLight> of(List<LightDto> dtos, SceneLimits limits, MappingProblems problems) {
        List<PointLight> lights = new ArrayList<>();
        if (dtos == null) {
            lights.add(new PointLight(vec(SceneDefaults.LIGHT_POSITION), Colors.linear(SceneDefaults.LIGHT_COLOR),
                    SceneDefaults.LIGHT_INTENSITY, false));
            return lights;
        }
        problems.atMost("lights", dtos.size(), limits.maxLights(), "lights");
        for (int i = 0; i < dtos.size() && i < limits.maxLights(); i++) {
            LightDto.Point l = (LightDto.Point) dtos.get(i);
            lights.add(new PointLight(vec(or(l.position(), SceneDefaults.LIGHT_POSITION)),
                    Colors.linear(or(l.color(), SceneDefaults.LIGHT_COLOR)),
                    or(l.intensity(), SceneDefaults.LIGHT_INTENSITY), Boolean.TRUE.equals(l.falloff())));
        }
        return lights;
    }
}
