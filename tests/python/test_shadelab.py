"""The Python module shadelab: its readers, normals and shading, from Python
as any VTK class (the build tree's module on PYTHONPATH)."""

import json
import math
import os
import unittest

import shadelab
from vtkmodules.vtkFiltersCore import vtkTriangleFilter
from vtkmodules.vtkFiltersSources import vtkPlaneSource
from vtkmodules.vtkRenderingCore import (vtkActor, vtkPolyDataMapper,
                                         vtkRenderer, vtkRenderWindow,
                                         vtkWindowToImageFilter)
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401 (the OpenGL classes)

MESHES = os.environ["SHADELAB_TEST_MESHES"]


def read(reader_class, name):
    reader = reader_class()
    reader.SetFileName(os.path.join(MESHES, name))
    reader.Update()
    return reader


class Readers(unittest.TestCase):
    def test_each_format_reads_triangles(self):
        for reader_class, name in [
                (shadelab.vtkShadelabOBJReader, "teapot-quads.obj"),
                (shadelab.vtkShadelabPLYReader, "teapot-fine.ply"),
                (shadelab.vtkShadelabSTLReader, "teapot.stl"),
                (shadelab.vtkShadelabOFFReader, "teapot.off"),
                (shadelab.vtkShadelabGLTFReader,
                 "/usr/share/assimp/models/glTF2/BoxTextured-glTF/BoxTextured.gltf"),
                (shadelab.vtkShadelabMeshReader, "teapot-quads.obj")]:
            with self.subTest(reader=reader_class.__name__):
                self.assertGreater(read(reader_class, name).GetOutput().GetNumberOfPolys(), 0)


class Normals(unittest.TestCase):
    def test_one_unit_normal_per_point(self):
        reader = read(shadelab.vtkShadelabMeshReader, "teapot.obj")
        normals = shadelab.vtkShadelabMeshNormals()
        normals.SetInputConnection(reader.GetOutputPort())
        self.assertTrue(normals.SetWeightingByName("angle"))
        normals.Update()
        mesh = normals.GetOutput()
        self.assertEqual(mesh.GetNumberOfPolys(), reader.GetOutput().GetNumberOfPolys())
        vectors = mesh.GetPointData().GetNormals()
        self.assertEqual(vectors.GetNumberOfTuples(), mesh.GetNumberOfPoints())
        for i in range(vectors.GetNumberOfTuples()):
            self.assertAlmostEqual(math.sqrt(sum(c * c for c in vectors.GetTuple3(i))), 1, places=6)


class Shading(unittest.TestCase):
    """The lecture's shading attached to a plain VTK pipeline: a plane facing
    the camera, orthographic, so V is (0, 0, 1) at every pixel; in triangles,
    which flat needs (it reads one face normal per triangle)."""

    SIDE = 32

    def render(self, attach):
        plane = vtkPlaneSource()
        plane.SetOrigin(-1, -1, 0)
        plane.SetPoint1(1, -1, 0)
        plane.SetPoint2(-1, 1, 0)
        triangles = vtkTriangleFilter()
        triangles.SetInputConnection(plane.GetOutputPort())
        mapper = vtkPolyDataMapper()
        mapper.SetInputConnection(triangles.GetOutputPort())
        actor = vtkActor()
        actor.SetMapper(mapper)
        renderer = vtkRenderer()
        renderer.AddActor(actor)
        camera = renderer.GetActiveCamera()
        camera.SetPosition(0, 0, 5)
        camera.SetParallelProjection(True)
        camera.SetParallelScale(0.5)
        window = vtkRenderWindow()
        window.SetOffScreenRendering(True)
        window.SetSize(self.SIDE, self.SIDE)
        window.AddRenderer(renderer)
        attach(actor, renderer)
        window.Render()
        grab = vtkWindowToImageFilter()
        grab.SetInput(window)
        grab.Update()
        image = grab.GetOutput()
        centre = self.SIDE // 2
        return [image.GetScalarComponentAsDouble(centre, centre, 0, c) for c in range(3)]

    def test_attached_shading_is_the_lectures_equation(self):
        # Blinn-Phong, bronze, Ia 0.2, a directional light 60 degrees off the
        # normal: N.L = cos 60, N.H = cos 30, unclamped in every channel; the
        # same at every point of the plane, so under phong and flat alike.
        angle = math.radians(60)
        with open(os.environ["SHADELAB_MATERIALS"]) as table:
            bronze = json.load(table)["materials"]["bronze"]
        n_dot_h = math.cos(angle / 2)
        expected = [255 * (bronze["ka"][c] * 0.2 + bronze["kd"][c] * math.cos(angle)
                           + bronze["ks"][c] * n_dot_h ** bronze["ns"]) for c in range(3)]
        for rule in ("phong", "flat"):
            with self.subTest(rule=rule):
                shading = shadelab.vtkShadelabShading()
                self.assertTrue(shading.SetShadingRuleByName(rule))
                self.assertTrue(shading.SetReflectionModelByName("blinn"))
                self.assertTrue(shading.SetMaterialByName("bronze"))
                shading.SetAmbientIntensity(0.2, 0.2, 0.2)
                shading.AddDirectionalLight(0, -math.sin(angle), -math.cos(angle))
                shaded = self.render(lambda actor, renderer: shading.Attach(actor, renderer))
                for channel, (got, want) in enumerate(zip(shaded, expected)):
                    # One level of 255: the GPU computes in float and rounds once.
                    self.assertLessEqual(abs(got - want), 1,
                                         f"channel {channel}: {shaded} vs {expected}")

        # Without the attachment VTK lights the same actor its own way.
        plain = self.render(lambda actor, renderer: None)
        self.assertGreater(max(abs(a - b) for a, b in zip(plain, shaded)), 10)

    def test_unknown_names_change_nothing(self):
        shading = shadelab.vtkShadelabShading()
        self.assertFalse(shading.SetShadingRuleByName("smooth"))
        self.assertFalse(shading.SetReflectionModelByName("cook-torrance"))
        self.assertFalse(shading.SetMaterialByName("unobtainium"))


if __name__ == "__main__":
    unittest.main()
