using SoftBodyDynamics.Authoring;
using SoftBodyDynamics.Editor;
using SoftBodyDynamics.Solvers;
using UnityEditor;
using UnityEditor.SceneManagement;
using UnityEngine;
using UnityEngine.SceneManagement;

namespace SoftBodyDynamics.Samples.WaterTap
{
    /// <summary>
    /// Builds the "Water Tap" sample next to this script: a main scene (camera, light, one SubScene) and the SubScene it
    /// loads: a 1 m basin (a floor plane and four box walls, all particle colliders), a fluid of water (Entities storage,
    /// every particle an instance of a small sphere prefab drawn by Entities Graphics), a tap pouring 400 particles/s down
    /// into the basin and a drain in one corner of the floor. Switch the fluid's Preset to Honey or Lava in its inspector.
    /// Menu: Tools ▸ Soft Body Dynamics ▸ Samples ▸ Build Water Tap Scene.
    /// </summary>
    static class WaterTapSceneBuilder
    {
        const string k_MenuPath = "Tools/Soft Body Dynamics/Samples/Build Water Tap Scene";
        const string k_ScriptName = nameof(WaterTapSceneBuilder);
        const string k_MainSceneName = "WaterTap";
        const string k_SubSceneName = "WaterTap_SubScene";
        /// <summary>Particle spacing of the fluid (m).</summary>
        const float k_Spacing = 0.025f;

        [MenuItem(k_MenuPath)]
        static void Build()
        {
            if (!SampleSceneBuilder.TryBegin("Water Tap sample", k_ScriptName, "WaterTap", k_MainSceneName, k_SubSceneName,
                    out SampleScenePaths paths, out Material template))
                return;

            string materialFolder = SampleSceneBuilder.EnsureFolder(paths.Folder, "Materials");
            Material water = SampleSceneBuilder.CreateMaterial(template, $"{materialFolder}/Water.mat", new Color(0.3f, 0.55f, 0.95f));
            Material basin = SampleSceneBuilder.CreateMaterial(template, $"{materialFolder}/Basin.mat", new Color(0.75f, 0.75f, 0.78f));
            Material floor = SampleSceneBuilder.CreateMaterial(template, $"{materialFolder}/Floor.mat", new Color(0.32f, 0.33f, 0.36f));

            Scene main = EditorSceneManager.NewScene(NewSceneSetup.EmptyScene, NewSceneMode.Single);
            SampleSceneBuilder.AddCamera(main, new Vector3(0f, 1.4f, -2.2f), Quaternion.Euler(25f, 0f, 0f));
            SampleSceneBuilder.AddLight(main);

            // The particle prefab: a sphere the size of one particle (diameter = spacing), drawn by Entities Graphics.
            string prefabFolder = SampleSceneBuilder.EnsureFolder(paths.Folder, "Prefabs");
            GameObject sphere = SampleSceneBuilder.CreateVisual("Water Particle", PrimitiveType.Sphere, water, main);
            sphere.transform.localScale = new Vector3(k_Spacing, k_Spacing, k_Spacing);
            sphere.AddComponent<MetaballParticleAuthoring>().radius = 0.5f * k_Spacing;
            GameObject prefab = PrefabUtility.SaveAsPrefabAsset(sphere, $"{prefabFolder}/WaterParticle.prefab");
            Object.DestroyImmediate(sphere);

            Scene sub = EditorSceneManager.NewScene(NewSceneSetup.EmptyScene, NewSceneMode.Additive);
            SampleSceneBuilder.AddFloor(sub, floor, Vector3.zero);
            AddWall(sub, basin, "Wall −X", new Vector3(-0.55f, 0.15f, 0f), new Vector3(0.1f, 0.3f, 1.2f));
            AddWall(sub, basin, "Wall +X", new Vector3(0.55f, 0.15f, 0f), new Vector3(0.1f, 0.3f, 1.2f));
            AddWall(sub, basin, "Wall −Z", new Vector3(0f, 0.15f, -0.55f), new Vector3(1.0f, 0.3f, 0.1f));
            AddWall(sub, basin, "Wall +Z", new Vector3(0f, 0.15f, 0.55f), new Vector3(1.0f, 0.3f, 0.1f));

            var fluidObject = new GameObject("Water");
            SceneManager.MoveGameObjectToScene(fluidObject, sub);
            fluidObject.transform.position = new Vector3(0f, 0.5f, 0f);
            FluidAuthoring fluid = fluidObject.AddComponent<FluidAuthoring>();
            fluid.preset = FluidAuthoringPreset.Water;
            fluid.particleSpacing = k_Spacing;
            fluid.domainSize = new Vector3(1f, 1f, 1f);
            fluid.particleBudget = 8000;
            fluid.speedOfSound = 10f;
            fluid.storage = FluidStorage.Entities;
            fluid.particlePrefab = prefab.GetComponent<MetaballParticleAuthoring>();
            // Drawn as a liquid surface by the Fluid Renderer Feature, where the URP renderer has it.
            FluidSurfaceAuthoring surface = fluidObject.AddComponent<FluidSurfaceAuthoring>();
            surface.look = FluidLookPreset.Water;

            var tapObject = new GameObject("Tap");
            SceneManager.MoveGameObjectToScene(tapObject, sub);
            tapObject.transform.position = new Vector3(-0.2f, 0.85f, 0f);
            tapObject.transform.rotation = Quaternion.Euler(90f, 0f, 0f);
            FluidTapAuthoring tap = tapObject.AddComponent<FluidTapAuthoring>();
            tap.fluid = fluid;
            tap.shape = FluidTapShape.Disc;
            tap.radius = 0.04f;
            tap.speed = 1.5f;
            tap.rate = 400f;
            tap.lifetime = 0f;
            tap.lifetimeRandom = 0f;
            // Particles live until the drain takes them; the cap keeps the steady state within the budget.
            tap.maxAlive = 6000;

            var drainObject = new GameObject("Drain");
            SceneManager.MoveGameObjectToScene(drainObject, sub);
            drainObject.transform.position = new Vector3(0.4f, 0.02f, 0.4f);
            FluidDrainAuthoring drain = drainObject.AddComponent<FluidDrainAuthoring>();
            drain.fluid = fluid;
            drain.shape = ColliderShapeType.Box;
            drain.size = new Vector3(0.2f, 0.06f, 0.2f);

            SampleSceneBuilder.SaveWithSubScene(main, sub, paths);
            Debug.Log($"Water Tap sample built: {paths.MainScene} (open) and {paths.SubScene}. Press Play; switch the Water's Preset to Honey or Lava in its inspector.");
        }

        static void AddWall(Scene scene, Material material, string name, Vector3 position, Vector3 size)
        {
            GameObject wall = SampleSceneBuilder.CreateVisual(name, PrimitiveType.Cube, material, scene);
            wall.transform.position = position;
            wall.transform.localScale = size;
            ParticleColliderAuthoring collider = wall.AddComponent<ParticleColliderAuthoring>();
            collider.shape = ColliderShapeType.Box;
            collider.size = Vector3.one;
        }
    }
}
