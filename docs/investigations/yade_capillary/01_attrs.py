for n in ["CapillarityEngine","Ip2_FrictMat_FrictMat_CapillaryMindlinPhysDelaunay","CapillaryMindlinPhysDelaunay","Law2_ScGeom_ImplicitLubricationPhys"]:
    o=eval(n)()
    print(n, o.dict())
    print((type(o).__doc__ or '')[:3000])
    print('----')
