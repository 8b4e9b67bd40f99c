"""A run in a periodic cell through the module and in ParaView: the quick periodic biaxial
preset, its shearing cut to an axial strain of 0.01. Run.cell_series is the cell's h at each
sample, so its area det h and its stretch h22 must give the series' own area and axial strain
columns (which the engine measures from the cell's deformation gradient, not from h); the VTK
cell outline of each frame is the parallelogram 0, h1, h1 + h2, h2 of that sample's h (VTK's
own reader), and no contact line crosses the cell (each goes to the image i touches)."""
import os
import shutil
import unittest
import xml.etree.ElementTree as ET

import numpy as np

import grainlab
from support import WORK, optional_module

vtk = optional_module("vtk", "python3-vtk9")
if vtk is not None:
    from vtk.util.numpy_support import vtk_to_numpy


def read(path):
    reader = vtk.vtkXMLPolyDataReader()
    reader.SetFileName(path)
    reader.Update()
    if reader.GetErrorCode() != 0:
        raise RuntimeError(f"VTK could not read {path}")
    return reader.GetOutput()


class CellRunTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        scene = grainlab.preset("periodic-biaxial-circular-quick")
        scene["assembly"]["specimen_diameter"] = 0.06  # the quick ring's size: cheap, and enough here
        scene["stages"][-1]["target_axial_strain"] = 0.01
        scene.setdefault("output", {}).update({"vtk": True, "vtk_every": 1})
        cls.out = os.path.join(WORK, "cell-run")
        shutil.rmtree(cls.out, ignore_errors=True)
        cls.result = grainlab.run(scene, out=cls.out, progress=False)

    def test_completed_with_a_cell(self):
        self.assertEqual(self.result.status, "completed", self.result.summary.get("error"))
        self.assertEqual(self.result.cell.shape, (2, 2))
        self.assertEqual(self.result.cell_series.shape, (len(self.result.series), 2, 2))
        self.assertGreater(len(self.result.series), 5)

    def test_cell_gives_the_series_area_and_axial_strain(self):
        h = self.result.cell_series
        series = self.result.series
        area = h[:, 0, 0] * h[:, 1, 1] - h[:, 0, 1] * h[:, 1, 0]
        # The same doubles det h: equal to rounding.
        np.testing.assert_allclose(area, series["area"], rtol=1e-12)
        # Axial strain 1 - F22 / F22(ref), ref the shearing stage's start; in a biaxial cell h
        # stays diagonal, so h22 / h22(ref) is that stretch (to rounding of the two products).
        shearing = np.flatnonzero(series["stage"] == series["stage"][-1])
        ref = h[shearing[0] - 1, 1, 1] if shearing[0] > 0 else h[shearing[0], 1, 1]
        strain = 1 - h[shearing, 1, 1] / ref
        measured = series["axial_strain"][shearing]
        # The reference is the stage's start, between the last row before it and its first row:
        # compare increments, which do not depend on where the reference sits.
        np.testing.assert_allclose(np.diff(strain), np.diff(measured), atol=1e-12)
        self.assertGreater(measured[-1], 0.009)
        np.testing.assert_array_equal(self.result.cell, h[-1])

    def test_final_contacts_give_the_series_stress(self):
        # Love's formula from the final contacts (grainlab.stress with the run's cell) over
        # det h: the last series row's stress (the engine's own, with branch vectors to the
        # nearest images). Without the cell a branch vector across an edge spans the cell.
        last = self.result.series[-1]
        s = grainlab.stress(self.result.contacts(), last["area"], particles=self.result.particles(),
                            cell=self.result.cell)
        fabric = grainlab.anisotropy(self.result.contacts(), particles=self.result.particles(), cell=self.result.cell)
        self.assertAlmostEqual(fabric["a_c"], last["a_c"], delta=1e-12)
        for k in ("sigma11", "sigma22", "sigma12", "sigma21"):
            self.assertAlmostEqual(s[k] / 1e3, last[k] / 1e3, delta=1e-9 * abs(last["p"]) / 1e3, msg=k)

    def test_contacts_final_csv_is_the_modules(self):
        # The file the CLI's analysis reads has the same branch vectors as Run.contacts().
        csv = grainlab.read_csv(os.path.join(self.out, "contacts_final.csv"))
        mine = self.result.contacts()
        for k in ("ljx", "ljy", "lix", "liy"):
            np.testing.assert_array_equal(csv[k], mine[k], err_msg=k)

    @unittest.skipIf(vtk is None, "left out: configured with -DGRAINLAB_PYTHON_OPTIONAL_MODULES=OFF")
    def test_vtk_cell_outline_is_h(self):
        vtkdir = os.path.join(self.out, "vtk")
        frames = ET.parse(os.path.join(vtkdir, "run.pvd")).getroot().findall("./Collection/DataSet")
        cells = [d.get("file") for d in frames if d.get("file").startswith("cell_")]
        contacts = [d.get("file") for d in frames if d.get("file").startswith("contacts_")]
        # vtk_every = 1: a frame per sample, each with its outline.
        self.assertEqual(len(cells), len(self.result.series))
        for k, name in enumerate(cells):
            data = read(os.path.join(vtkdir, name))
            points = vtk_to_numpy(data.GetPoints().GetData())[:, :2]
            h = self.result.cell_series[k]
            h1, h2 = h[:, 0], h[:, 1]
            np.testing.assert_array_equal(points, np.array([[0, 0], h1, h1 + h2, h2]), err_msg=name)
            self.assertEqual(data.GetNumberOfLines(), 1)
            line = data.GetLines()
            ids = vtk.vtkIdList()
            line.InitTraversal()
            line.GetNextCell(ids)
            self.assertEqual([ids.GetId(i) for i in range(ids.GetNumberOfIds())], [0, 1, 2, 3, 0])
            np.testing.assert_array_equal(vtk_to_numpy(data.GetCellData().GetArray("h1"))[0, :2], h1)
        # The last frame's contacts: every line shorter than the largest contact reach (two
        # bounding radii), none drawn across the cell to the far side.
        data = read(os.path.join(vtkdir, contacts[-1]))
        ends = vtk_to_numpy(data.GetPoints().GetData())[:, :2]
        lengths = np.hypot(*(ends[1::2] - ends[0::2]).T)
        reach = 2 * np.max(self.result.particles()["radius"])
        self.assertGreater(len(lengths), 100)
        self.assertLessEqual(lengths.max(), reach)


if __name__ == "__main__":
    unittest.main()
