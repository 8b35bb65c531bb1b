package studio.server.scene.compiling;

/** The triangles a scene's meshes and models may still have together (studio.limits.max-triangles). */
final class TriangleBudget {

    private int left;

    TriangleBudget(int max) {
        this.left = max;
    }

    /** Triangles still allowed (negative once overspent). */
    int left() {
        return left;
    }

    void spend(int triangles) {
        left -= triangles;
    }
}
