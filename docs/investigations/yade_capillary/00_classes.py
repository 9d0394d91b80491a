import yade.system
names = ["Law2_ScGeom_ViscElCapPhys_Basic","Ip2_ViscElCapMat_ViscElCapMat_ViscElCapPhys","ViscElCapMat","ViscElCapPhys",
 "Law2_ScGeom_CapillaryPhys_Capillarity","Ip2_FrictMat_FrictMat_CapillaryPhys","Ip2_FrictMat_FrictMat_MindlinCapillaryPhys",
 "MindlinCapillaryPhys","CapillaryPhys","Law2_ScGeom_ImplicitLubricationPhys","Ip2_FrictMat_FrictMat_LubricationPhys",
 "Law2_ScGeom_MindlinPhys_Mindlin","Ip2_FrictMat_FrictMat_MindlinPhys","Ig2_Facet_Sphere_ScGeom","Ig2_Facet_Sphere_ScGeom6D",
 "Ip2_ViscElMat_ViscElMat_ViscElPhys","Law2_ScGeom_ViscElPhys_Basic","Ip2_FrictMat_FrictMat_FrictPhys","Law2_ScGeom_FrictPhys_CundallStrack",
 "LiqControl","CapillaryStressRecorder","Ip2_ViscElCapMat_ViscElMat_ViscElCapPhys","Ip2_FrictMat_ViscElCapMat_ViscElCapPhys",
 "Law2_ScGeom_CapillaryPhys_Capillarity","PartialSatClayEngine","TwoPhaseFlowEngine","UnsaturatedEngine","Law2_ScGeom_FrictPhys_CundallStrack"]
import yade.wrapper as W
for n in names:
    print(n, hasattr(W, n))
allc = [c for c in dir(W) if 'ap' in c.lower() and ('Cap' in c or 'Liq' in c or 'Lub' in c)]
print(allc)
for n in ["Law2_ScGeom_CapillaryPhys_Capillarity","Law2_ScGeom_ViscElCapPhys_Basic","Ip2_ViscElCapMat_ViscElCapMat_ViscElCapPhys","ViscElCapMat","ViscElCapPhys","Ip2_FrictMat_FrictMat_MindlinCapillaryPhys","MindlinCapillaryPhys"]:
    if hasattr(W,n):
        o = getattr(W,n)()
        try: print(n, o.dict())
        except Exception as e: print(n, e)
import yade.config; print(yade.config.features)
