package studio.server.preview;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

import studio.server.preview.patch.JsonPatch;
import tools.jackson.databind.json.JsonMapper;

/** Which objects a patch changed, told by its paths. */
class ObjectOriginsTest {

    private static final JsonMapper JSON = JsonMapper.builder().build();

    private static ObjectOrigins after(int count, String patch) {
        ObjectOrigins origins = new ObjectOrigins(count);
        origins.follow(JsonPatch.of(JSON.readTree(patch.replace('\'', '"'))));
        return origins;
    }

    @Test
    void aMemberOfAnObjectChangesThatObjectAlone() {
        ObjectOrigins origins = after(4, "[{'op':'replace','path':'/objects/2/center/0','value':1}]");
        assertArrayEquals(new int[] {0, 1, -1, 3}, origins.origins());
        assertFalse(origins.frameChanged());
        assertEquals(1, origins.changed());
    }

    @Test
    void addingRemovingAndMovingObjectsShiftsTheOthers() {
        assertArrayEquals(new int[] {0, 1, 2, -1}, after(3, "[{'op':'add','path':'/objects/-','value':{}}]").origins());
        assertArrayEquals(new int[] {-1, 0, 1, 2}, after(3, "[{'op':'add','path':'/objects/0','value':{}}]").origins());
        assertArrayEquals(new int[] {0, 2}, after(3, "[{'op':'remove','path':'/objects/1'}]").origins());
        assertArrayEquals(new int[] {1, 2, 0}, after(3, "[{'op':'move','from':'/objects/0','path':'/objects/2'}]").origins());
        assertArrayEquals(new int[] {0, 1, 2, -1},
                after(3, "[{'op':'copy','from':'/objects/0','path':'/objects/3'}]").origins());
        assertArrayEquals(new int[] {0, -1, 2}, after(3, "[{'op':'test','path':'/objects/0','value':{}},"
                + "{'op':'replace','path':'/objects/1','value':{}}]").origins());
    }

    @Test
    void anythingOutsideTheObjectsChangesTheFrame() {
        ObjectOrigins camera = after(2, "[{'op':'replace','path':'/camera/fov','value':40}]");
        assertTrue(camera.frameChanged());
        assertArrayEquals(new int[] {0, 1}, camera.origins());
        ObjectOrigins moved = after(2, "[{'op':'move','from':'/objects/1/material','path':'/lights/0/m'}]");
        assertTrue(moved.frameChanged());
        assertArrayEquals(new int[] {0, -1}, moved.origins());
    }

    @Test
    void theArrayOrTheSceneAsAWholeChangesEveryObject() {
        assertNull(after(2, "[{'op':'replace','path':'/objects','value':[]}]").origins());
        assertNull(after(2, "[{'op':'replace','path':'','value':{}}]").origins());
        assertTrue(after(2, "[{'op':'replace','path':'','value':{}}]").frameChanged());
        assertEquals(Integer.MAX_VALUE, after(2, "[{'op':'remove','path':'/objects'}]").changed());
    }
}
